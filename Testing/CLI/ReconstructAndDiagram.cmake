# Command-line tests of `flowrecon reconstruct` and `flowrecon diagram`
# (included from Testing/CLI/CMakeLists.txt after Basics.cmake: they use
# flowrecon_add_cli_test, _d, _w and Basics.cmake's fixture flowrecon_cli_vtm).
# RunCLI.cmake's VTM argument is used to check that a file was written (with no
# block list it only checks existence).

# Usage errors: exit code 2, an error line and a hint.
flowrecon_add_cli_test(ReconstructHelp EXIT 0 STDERR_LINES 0
  STDOUT "^Usage: flowrecon reconstruct INPUT -o OUT.vtu.*--tr.*--tp.*--profile.*--jumps"
  ARGS reconstruct --help)
flowrecon_add_cli_test(HelpListsNewCommands EXIT 0 STDERR_LINES 0
  STDOUT "reconstruct .*diagram " ARGS --help)
flowrecon_add_cli_test(ReconstructMissingOutput EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: 'reconstruct' needs an output file: -o OUT.vtu\nTry 'flowrecon reconstruct --help'"
  ARGS reconstruct "${_d}/tetrahedron.xyz")
flowrecon_add_cli_test(ReconstructOutputNotVtu EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: the output file must have the .vtu extension: 'out.vtp'"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o out.vtp)
flowrecon_add_cli_test(ReconstructBadThreshold EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: option '--tr' needs a number, not 'abc'"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o out.vtu --tr abc)
flowrecon_add_cli_test(ReconstructThresholdTooSmall EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: the reconstruction threshold --tr must be greater than 1"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o out.vtu --tr 1)
flowrecon_add_cli_test(ReconstructNegativePersistence EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: the persistence threshold --tp must be a finite number >= 0"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o out.vtu --tp -1)
flowrecon_add_cli_test(ReconstructBadJumps EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: option '--jumps' needs a positive integer"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o out.vtu --jumps 0)
# --compact, the default, is kept for compatibility; with --exact or --tr-max
# (which writes the exact cells) it is a contradiction.
flowrecon_add_cli_test(ReconstructCompactAndExact EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: --compact \\(the default\\) excludes --exact and --tr-max, which write the exact cells\nTry 'flowrecon reconstruct --help'"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o out.vtu --compact --exact)
flowrecon_add_cli_test(ReconstructCompactAndTrMax EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: --compact \\(the default\\) excludes --exact and --tr-max"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o out.vtu --compact --tr-max 3)
flowrecon_add_cli_test(DiagramMissingOutput EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: 'diagram' needs an output file: -o OUT.csv"
  ARGS diagram "${_d}/tetrahedron.xyz")
flowrecon_add_cli_test(DiagramBadExtension EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: the output file must have the .csv or .vtu extension: 'pd.txt'"
  ARGS diagram "${_d}/tetrahedron.xyz" -o pd.txt)

# Bad input: exit code 1, one line.
flowrecon_add_cli_test(ReconstructMissingFile EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: no_such_cloud\\.xyz: no such file\n$"
  ARGS reconstruct no_such_cloud.xyz -o out.vtu)
flowrecon_add_cli_test(DiagramCoplanar EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: [^\n]*/coplanar\\.xyz: [^\n]*coplanar"
  ARGS diagram "${_d}/coplanar.xyz" -o coplanar.csv)
flowrecon_add_cli_test(ReconstructOutputDirectoryMissing EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: no_such_directory/out\\.vtu: directory 'no_such_directory' does not exist"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o no_such_directory/out.vtu)

# Results on the regular tetrahedron (values by hand: edges sqrt 2, faces
# 2 sqrt(2/3), the maximum sqrt 3; ratios face/edge 1.1547 and
# maximum/face 1.0607, both < 2, so without simplification all 15 finite nodes
# are reconstructed at t_r 2; at t_r 1.1 only the 4 samples and the 6 edges,
# all at ratio 1 (equal edges join by horizontal extension at ratio 1)).
# The default output, Delaunay simplices on the samples: at t_r 2 the solid
# (the cell alone: its 4 faces are its own), at t_r 1.1 its 6 edges (b1 = 3); --compact is
# the same run.
flowrecon_add_cli_test(ReconstructTetrahedron EXIT 0 STDERR_LINES 0
  STDOUT "^[^\n]*tet_compact\\.vtu: 1 cells, 15 of 15 steps at t_r 2\nBetti numbers: 1 0 0\ncompact output: 0 triangles, 1 tetrahedra, 0 edges, 0 samples, 0\\.25 cells per sample; 0 triangles shared by two patches, 0 crossed twice by one walk, 0 voids without a maximum filled\ncompact output's Betti numbers 1 0 0\n$"
  VTM "${_w}/tet_compact.vtu"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o "${_w}/tet_compact.vtu" --tp 0 --tr 2)
flowrecon_add_cli_test(ReconstructCompactAlias EXIT 0 STDERR_LINES 0
  STDOUT "^[^\n]*tet_alias\\.vtu: 1 cells, 15 of 15 steps at t_r 2\nBetti numbers: 1 0 0\ncompact output: 0 triangles, 1 tetrahedra, 0 edges, 0 samples, 0\\.25 cells per sample; 0 triangles shared by two patches, 0 crossed twice by one walk, 0 voids without a maximum filled\ncompact output's Betti numbers 1 0 0\n$"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o "${_w}/tet_alias.vtu" --tp 0 --tr 2 --compact)
flowrecon_add_cli_test(ReconstructTetrahedronEdges EXIT 0 STDERR_LINES 3
  STDOUT "tet_compact_edges\\.vtu: 6 cells, 10 of 15 steps at t_r 1\\.1\nBetti numbers: 1 3 0\ncompact output: 0 triangles, 0 tetrahedra, 6 edges, 0 samples, 1\\.5 cells per sample;.*\ncompact output's Betti numbers 1 3 0\n"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o "${_w}/tet_compact_edges.vtu" --tp 0 --tr 1.1)
# --exact: the stable manifolds, 34 cells at t_r 2 (4 samples, 6 edges, each
# face's patch in 3 triangles about its centre, the cone of the cell over its
# 12 triangles); at t_r 1.1 the 4 samples and the 6 edges; the same from a
# stored flow complex.
flowrecon_add_cli_test(ReconstructTetrahedronExact EXIT 0 STDERR_LINES 0
  STDOUT "^[^\n]*tet_all\\.vtu: 34 cells, 15 of 15 steps at t_r 2\nBetti numbers: 1 0 0\n$"
  VTM "${_w}/tet_all.vtu"
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o "${_w}/tet_all.vtu" --tp 0 --tr 2 --exact)
flowrecon_add_cli_test(ReconstructTetrahedronEdgesExact EXIT 0 STDERR_LINES 0
  STDOUT "^[^\n]*tet_edges\\.vtu: 10 cells, 10 of 15 steps at t_r 1\\.1\nBetti numbers: 1 3 0\n$"
  FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS reconstruct "${_w}/tetrahedron.vtm" -o "${_w}/tet_edges.vtu" --tp 0 --tr 1.1
       --warn-window 1 --exact)
flowrecon_add_cli_test(ReconstructTetrahedronEdgesStored EXIT 0 STDERR_LINES 0
  STDOUT "^[^\n]*tet_edges_stored\\.vtu: 6 cells, 10 of 15 steps at t_r 1\\.1\nBetti numbers: 1 3 0\ncompact output: 0 triangles, 0 tetrahedra, 6 edges, 0 samples, 1\\.5 cells per sample;.*\ncompact output's Betti numbers 1 3 0\n$"
  FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS reconstruct "${_w}/tetrahedron.vtm" -o "${_w}/tet_edges_stored.vtu" --tp 0 --tr 1.1
       --warn-window 1)
# The regular tetrahedron (edge 2 sqrt 2) at t_r 1.1 is its 6 edges (b1 = 3);
# its faces (circumradius 2 sqrt(2/3)) close the 3 holes at t_r = 2/sqrt 3 =
# 1.1547, within the default window 1.1: warned, at a face's centre (spacing
# twice the circumradius, 3.26599) and at the centre (the cone's apex).
# --no-betti: neither the Betti numbers nor the warnings (only the summary line,
# and the compact output's counts).
flowrecon_add_cli_test(ReconstructNoBetti EXIT 0 STDERR_LINES 0
  STDOUT "^[^\n]*tet_nb\\.vtu: 6 cells, 10 of 15 steps at t_r 1\\.1\ncompact output: 0 triangles, 0 tetrahedra, 6 edges, [^\n]*filled\n$"
  FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS reconstruct "${_w}/tetrahedron.vtm" -o "${_w}/tet_nb.vtu" --tp 0 --tr 1.1 --no-betti)
flowrecon_add_cli_test(ReconstructNoBettiExact EXIT 0 STDERR_LINES 0
  STDOUT "^[^\n]*tet_nb_exact\\.vtu: 10 cells, 10 of 15 steps at t_r 1\\.1\n$"
  FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS reconstruct "${_w}/tetrahedron.vtm" -o "${_w}/tet_nb_exact.vtu" --tp 0 --tr 1.1 --no-betti
       --exact)
# A cloud's Betti numbers come from the Hasse diagram: no cell budget applies
# (at t_r 1.1 the tetrahedron is its six edges: three independent loops).
flowrecon_add_cli_test(ReconstructBettiBudget EXIT 0
  STDOUT "tet_budget\\.vtu: 6 cells, 10 of 15 steps at t_r 1\\.1\nBetti numbers: 1 3 0\n"
  FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS reconstruct "${_d}/tetrahedron.xyz" -o "${_w}/tet_budget.vtu" --tp 0 --tr 1.1
       --betti-max-cells 5)
# A saved complex's Betti numbers come from its Hasse diagram too (the filters
# compute them with the queue): no cell budget applies. The budget of the drawn
# cells' homology, their fallback, is TestTopologyAskedLater's.
flowrecon_add_cli_test(ReconstructBettiBudgetSaved EXIT 0
  STDOUT "^[^\n]*tet_budget_saved\\.vtu: 6 cells, 10 of 15 steps at t_r 1\\.1\nBetti numbers: 1 3 0\ncompact output: [^\n]*\ncompact output's Betti numbers 1 3 0\n$"
  FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS reconstruct "${_w}/tetrahedron.vtm" -o "${_w}/tet_budget_saved.vtu" --tp 0 --tr 1.1
       --betti-max-cells 5)
# The three loops of the six edges close at t_r 1.1547, each by another face:
# one warning at each of three face centres.
flowrecon_add_cli_test(ReconstructTetrahedronWarnings EXIT 0 STDERR_LINES 3
  STDERR "warning: under-sampled near \\(-?0\\.333333, -?0\\.333333, -?0\\.333333\\): spacing 3\\.26599; at t_r 1\\.1547 a hole closes"
  FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS reconstruct "${_w}/tetrahedron.vtm" -o "${_w}/tet_warn.vtu" --tp 0 --tr 1.1)
flowrecon_add_cli_test(ReconstructProfile EXIT 0 STDERR_LINES 0
  STDOUT "largest jumps of the profile.*\n  step [0-9]+: [0-9.]+ -> [0-9.]+, node [0-9]+, index [0-3], value [0-9.]+, at \\("
  VTM "${_w}/small_profile.csv"
  ARGS reconstruct "${_d}/small_cloud.xyz" -o "${_w}/small.vtu" --tr inf
    --profile "${_w}/small_profile.csv" --jumps 2)
flowrecon_add_cli_test(ReconstructQuiet EXIT 0 STDERR_LINES 0 STDOUT "^$"
  VTM "${_w}/small_quiet.vtu"
  ARGS reconstruct "${_d}/small_cloud.xyz" -o "${_w}/small_quiet.vtu" --quiet)
# H0: 3 finite + 1 essential, H1: 3 (edges killed by faces), H2: 1 (killed by the maximum).
flowrecon_add_cli_test(DiagramTetrahedron EXIT 0 STDERR_LINES 0
  STDOUT "tet_pd\\.csv: 8 pairs \\(4 3 1 in dimensions 0 1 2\\)"
  VTM "${_w}/tet_pd.csv"
  ARGS diagram "${_d}/tetrahedron.xyz" -o "${_w}/tet_pd.csv")
flowrecon_add_cli_test(DiagramStoredVtu EXIT 0 STDERR_LINES 0
  STDOUT "tet_pd\\.vtu: 8 pairs" VTM "${_w}/tet_pd.vtu" FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS diagram "${_w}/tetrahedron.vtm" -o "${_w}/tet_pd.vtu")
# A complex stored without stable manifolds (small, fast to write).
flowrecon_add_cli_test(ComplexNoStable EXIT 0 STDERR_LINES 0
  VTM "${_w}/small_nostable.vtm" FIXTURES_SETUP flowrecon_cli_nostable
  ARGS complex "${_d}/small_cloud.xyz" -o "${_w}/small_nostable.vtm" --no-stable --quiet)
# A complex saved without stable manifolds: the reconstruction draws them
# (its one warning: 30 samples are too few to check the answer).
flowrecon_add_cli_test(ReconstructNoStable EXIT 0 STDERR_LINES 1 STDERR "^warning: only 30 samples, too few to tell"
  STDOUT "small_nostable\\.vtu: [1-9][0-9]* cells" FIXTURES_REQUIRED flowrecon_cli_nostable
  ARGS reconstruct "${_w}/small_nostable.vtm" -o "${_w}/small_nostable.vtu")

# Command-line tests of help, usage errors, bad input, `flowrecon complex` and
# `flowrecon info`, corrupt files, a full disk, Ctrl-C and the memory guard
# (included from Testing/CLI/CMakeLists.txt, which defines flowrecon_add_cli_test,
# _d (inputs) and _w (outputs)).

# Help, version, usage errors (exit code 2, an error line and a hint).
flowrecon_add_cli_test(Help EXIT 0 STDERR_LINES 0
  STDOUT "^Usage: flowrecon COMMAND.*complex.*info" ARGS --help)
flowrecon_add_cli_test(CommandHelp EXIT 0 STDERR_LINES 0
  STDOUT "^Usage: flowrecon complex INPUT -o OUT.vtm.*--no-stable" ARGS complex --help)
flowrecon_add_cli_test(Version EXIT 0 STDOUT "^flowrecon ${PROJECT_VERSION} \\(VTK " ARGS --version)
flowrecon_add_cli_test(NoCommand EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: missing command\nTry 'flowrecon --help'" ARGS)
flowrecon_add_cli_test(UnknownCommand EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: unknown command 'frobnicate'\nTry 'flowrecon --help'" ARGS frobnicate)
flowrecon_add_cli_test(UnknownOption EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: unknown option '--frob' for 'complex'\nTry 'flowrecon complex --help'"
  ARGS complex "${_d}/tetrahedron.xyz" --frob -o out.vtm)
flowrecon_add_cli_test(MissingOptionValue EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: option '-o' needs a value" ARGS complex "${_d}/tetrahedron.xyz" -o)
flowrecon_add_cli_test(MissingInput EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: 'info' needs an INPUT file" ARGS info)
flowrecon_add_cli_test(MissingOutput EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: 'complex' needs an output file" ARGS complex "${_d}/tetrahedron.xyz")
flowrecon_add_cli_test(OutputNotVtm EXIT 2 STDERR_LINES 2
  STDERR "^flowrecon: the output file must have the .vtm extension: 'out.vtp'"
  ARGS complex "${_d}/tetrahedron.xyz" -o out.vtp)

# Bad input: exit code 1 and exactly one line naming the file (and the line).
flowrecon_add_cli_test(MissingFile EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: no_such_cloud\\.xyz: no such file\n$" ARGS info no_such_cloud.xyz)
flowrecon_add_cli_test(UnparsableLine EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: [^\n]*/bad_line\\.xyz:3: cannot parse 'abc' as a number"
  ARGS complex "${_d}/bad_line.xyz" -o bad_line.vtm)
flowrecon_add_cli_test(NotANumber EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: [^\n]*/nan\\.xyz:2: non-finite x coordinate 'nan'" ARGS info "${_d}/nan.xyz")
flowrecon_add_cli_test(TooFewPoints EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: [^\n]*/three_points\\.xyz: [^\n]*at least 4" ARGS info "${_d}/three_points.xyz")
flowrecon_add_cli_test(Coplanar EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: [^\n]*/coplanar\\.xyz: [^\n]*coplanar" ARGS complex "${_d}/coplanar.xyz" -o coplanar.vtm)
flowrecon_add_cli_test(OutputDirectoryMissing EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: no_such_directory/out\\.vtm: directory 'no_such_directory' does not exist"
  ARGS complex "${_d}/tetrahedron.xyz" -o no_such_directory/out.vtm)

# A line of separators only (found by fuzzing: read a field that is not there).
flowrecon_add_cli_test(CommaLineOff EXIT 1 STDERR_LINES 1
  STDERR "comma_line\\.off:1: expected the OFF header keyword" ARGS info "${_d}/comma_line.off")
flowrecon_add_cli_test(CommaLineObj EXIT 1 STDERR_LINES 1
  STDERR "comma_line\\.obj: no points found" ARGS info "${_d}/comma_line.obj")

# A compressed LAS scan: one line saying what to do, not "unknown extension".
flowrecon_add_cli_test(CompressedLas EXIT 1 STDERR_LINES 1
  STDERR "compressed_scan\\.laz: compressed LAS \\(LAZ\\) is not supported: decompress it to \\.las first"
  ARGS info "${_d}/compressed_scan.laz")

# Spacing some 1e-200 of the extent (found by fuzzing): the double constructions of
# critical points underflow; one line instead of a silently wrong complex (builds
# with CGAL's assertions on, as the sanitizer job's, stop at CGAL's check first).
flowrecon_add_cli_test(TinySpacing EXIT 1 STDERR_LINES 1
  STDERR "tiny_spacing\\.xyz: (points too close together|flow complex construction failed: CGAL ERROR)"
  ARGS info "${_d}/tiny_spacing.xyz")
# Coordinates near the largest doubles: a circumcentre beyond them is refused,
# not written as inf (a fuzz_core finding).
flowrecon_add_cli_test(BeyondDouble EXIT 1 STDERR_LINES 1
  STDERR "beyond_double\\.xyz: coordinates too large: a critical point lies beyond the largest double"
  ARGS info "${_d}/beyond_double.xyz")

# Results.
flowrecon_add_cli_test(ComplexWritesVtm EXIT 0 STDERR_LINES 0
  STDOUT "tetrahedron\\.vtm: nodes by index 4 6 4 1, "
  VTM "${_w}/tetrahedron.vtm" VTM_BLOCKS "CriticalPoints,HasseDiagram,StableManifolds,UnstableManifolds"
  FIXTURES_SETUP flowrecon_cli_vtm
  ARGS complex "${_d}/tetrahedron.xyz" -o "${_w}/tetrahedron.vtm")
flowrecon_add_cli_test(InfoTetrahedron EXIT 0 STDERR_LINES 0
  STDOUT "input points: +4\n.*nodes by index: +4 6 4 1 .*Euler characteristic: +1 .*timings.*Total"
  ARGS info "${_d}/tetrahedron.xyz")
flowrecon_add_cli_test(InfoSmallCloud EXIT 0 STDERR_LINES 0
  STDOUT "input points: +30\n.*Euler characteristic: +1 " ARGS info --quiet "${_d}/small_cloud.xyz")
flowrecon_add_cli_test(InfoStoredComplex EXIT 0 STDERR_LINES 0
  STDOUT "\\(flow complex file\\).*nodes by index: +4 6 4 1 .*Euler characteristic: +1 "
  FIXTURES_REQUIRED flowrecon_cli_vtm ARGS info "${_w}/tetrahedron.vtm")
flowrecon_add_cli_test(ComplexOfComplex EXIT 1 STDERR_LINES 1
  STDERR "already a flow complex" FIXTURES_REQUIRED flowrecon_cli_vtm
  ARGS complex "${_w}/tetrahedron.vtm" -o again.vtm)

# Corrupt VTK XML files: a last cell offset raised by 2^32 made VTK allocate
# 32 GB and abort, a missing primary element made it crash; one line naming
# the file instead (VTK's reader runs in a child process). Copies of the
# complex above, corrupted by CorruptXML.py.
add_test(NAME cli.CorruptFilesSetup COMMAND "${FLOWRECON_TEST_PYTHON}"
  "${CMAKE_CURRENT_LIST_DIR}/CorruptXML.py" "${_w}/tetrahedron.vtm" "${_w}/corrupt")
set_tests_properties(cli.CorruptFilesSetup PROPERTIES
  FIXTURES_SETUP flowrecon_cli_corrupt FIXTURES_REQUIRED flowrecon_cli_vtm)
flowrecon_add_cli_test(CorruptCloud EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: [^\n]*/corrupt/cloud\\.vtp: (out of memory|cannot read VTK XML file) \\("
  FIXTURES_REQUIRED flowrecon_cli_corrupt ARGS info "${_w}/corrupt/cloud.vtp")
flowrecon_add_cli_test(CorruptComplexPiece EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: [^\n]*/corrupt/tetrahedron\\.vtm: (out of memory|cannot read VTK XML file) \\("
  FIXTURES_REQUIRED flowrecon_cli_corrupt
  ARGS reconstruct "${_w}/corrupt/tetrahedron.vtm" -o "${_w}/corrupt.vtu")
flowrecon_add_cli_test(CorruptComplexNoPrimary EXIT 1 STDERR_LINES 1
  STDERR "^flowrecon: [^\n]*/corrupt/noprimary\\.vtm: cannot read VTK XML file \\("
  FIXTURES_REQUIRED flowrecon_cli_corrupt
  ARGS reconstruct "${_w}/corrupt/noprimary.vtm" -o "${_w}/corrupt.vtu")

# A full disk is named as such (/dev/full fails every write with ENOSPC; the
# .vtu and .csv outputs are links to it).
if (EXISTS /dev/full)
  add_test(NAME cli.FullDiskSetup COMMAND sh -c
    "ln -sf /dev/full '${_w}/full.vtu' && ln -sf /dev/full '${_w}/full.csv'")
  set_tests_properties(cli.FullDiskSetup PROPERTIES FIXTURES_SETUP flowrecon_cli_full)
  flowrecon_add_cli_test(FullDiskProfile EXIT 1 STDERR_LINES 1
    STDERR "^flowrecon: /dev/full: cannot write \\(no space left on device\\)\n$"
    ARGS reconstruct "${_d}/tetrahedron.xyz" -o "${_w}/full_profile.vtu" --quiet --profile /dev/full)
  flowrecon_add_cli_test(FullDiskVtu EXIT 1 STDERR_LINES 1
    STDERR "^flowrecon: [^\n]*/full\\.vtu: cannot write \\(no space left on device\\)\n$"
    FIXTURES_REQUIRED flowrecon_cli_full
    ARGS reconstruct "${_d}/tetrahedron.xyz" -o "${_w}/full.vtu" --quiet)
  flowrecon_add_cli_test(FullDiskCsv EXIT 1 STDERR_LINES 1
    STDERR "^flowrecon: [^\n]*/full\\.csv: cannot write \\(no space left on device\\)\n$"
    FIXTURES_REQUIRED flowrecon_cli_full
    ARGS diagram "${_d}/tetrahedron.xyz" -o "${_w}/full.csv" --quiet)
endif ()

# Ctrl-C stops a long run cleanly (needs coreutils' timeout to send SIGINT).
find_program(FLOWRECON_TIMEOUT_PROGRAM timeout)
mark_as_advanced(FLOWRECON_TIMEOUT_PROGRAM)
if (FLOWRECON_TIMEOUT_PROGRAM)
  add_test(NAME cli.Interrupt
    COMMAND sh "${CMAKE_CURRENT_LIST_DIR}/RunInterrupt.sh" "$<TARGET_FILE:flowrecon>" "${_w}")
  set_tests_properties(cli.Interrupt PROPERTIES TIMEOUT 120)
endif ()

# The child that goes on after reading a stored flow complex dies of a signal:
# the waiting parent says so in one line (needs Linux's /proc to find the child).
if (CMAKE_SYSTEM_NAME STREQUAL "Linux")
  add_test(NAME cli.ChildDeath
    COMMAND sh "${CMAKE_CURRENT_LIST_DIR}/RunChildDeath.sh" "$<TARGET_FILE:flowrecon>" "${_w}")
  set_tests_properties(cli.ChildDeath PROPERTIES TIMEOUT 300)
endif ()

# Under an address-space limit a run that would not fit stops with the memory
# guard's one line (estimate, what is available, what to do), not an abort;
# one of the default output ends in one line or its file.
add_test(NAME cli.MemoryGuard
  COMMAND sh "${CMAKE_CURRENT_LIST_DIR}/RunUnderLimit.sh" "$<TARGET_FILE:flowrecon>" "${_w}")
set_tests_properties(cli.MemoryGuard PROPERTIES TIMEOUT 400)
# So must a run in a cgroup whose memory limit it would exceed (the kernel
# kills without a word): needs root and a writable cgroup, else skipped.
add_test(NAME cli.MemoryGuardCgroup
  COMMAND sh "${CMAKE_CURRENT_LIST_DIR}/RunUnderCgroup.sh" "$<TARGET_FILE:flowrecon>" "${_w}")
set_tests_properties(cli.MemoryGuardCgroup PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77)

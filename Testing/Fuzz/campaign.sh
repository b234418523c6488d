#!/usr/bin/env bash
# Long fuzz campaign (Testing/Fuzz/README.md): each target in turn for SECONDS
# (default 1200) on one core, in libFuzzer's fork mode with one worker, which
# goes on after a crash, an out-of-memory or a timeout and keeps every
# reproducer. The corpus grows in BUILD/campaign/TARGET/corpus (seeded from
# Testing/Fuzz/corpus/TARGET; kept between campaigns), reproducers go to
# BUILD/campaign/TARGET/artifacts, the log to BUILD/campaign/TARGET.log.
# Usage: bash Testing/Fuzz/campaign.sh [SECONDS] [TARGET...]
#   (BUILD = build-fuzz, configured by .ci/fuzz-smoke or as README.md says;
#    TARGET among core point_cloud_reader stored_complex, default all)
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-1200}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(core point_cloud_reader stored_complex)
build=${FLOWRECON_FUZZ_BUILD:-build-fuzz}
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/.ci/lsan.supp:print_suppressions=0"
for t in "${targets[@]}"; do
  dir="$build/campaign/$t"
  mkdir -p "$dir/corpus" "$dir/artifacts"
  cp -n Testing/Fuzz/corpus/"$t"/* "$dir/corpus/" 2>/dev/null || true
  echo "== $t: $seconds s, log $dir.log"
  start=$(date +%s)
  dict=()
  [ "$t" = core ] || dict=(-dict=Testing/Fuzz/vtk.dict)
  "$build/bin/fuzz_$t" -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
    -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 "${dict[@]}" \
    -artifact_prefix="$dir/artifacts/" "$dir/corpus" > "$dir.log" 2>&1 || true
  end=$(date +%s)
  # The fork-mode status lines: "#EXECS: cov: C ft: F corp: N exec/s E oom/timeout/crash: O/T/C ..."
  last=$(grep -E '^#[0-9]+: cov:' "$dir.log" | tail -1 || true)
  echo "   $((end - start)) s; last status: ${last:-none}"
  echo "   artifacts: $(ls "$dir/artifacts" | wc -l) in $dir/artifacts"
done

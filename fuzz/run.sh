#!/usr/bin/env bash
# Runs the fuzz targets of a GRIT_FUZZ build (make fuzz): each from a seed corpus made of what the
# project ships (the case files, with a few --set lines; the STL files) and the inputs that once found a
# problem (fuzz/regressions/<target>/, each also a test in tests/), growing its own corpus in
# BUILD/fuzz-corpus/<target>.
#   bash fuzz/run.sh BUILD SECONDS        each target for SECONDS (a search: new inputs are kept)
#   bash fuzz/run.sh BUILD 0 RUNS         each target replays its corpus, then RUNS inputs from seed 1
#                                         (deterministic: what CI runs)
# A crash, hang (over 10 s), leak, sanitizer report or exception other than the reader's InputError stops
# the run with the input that caused it in BUILD/fuzz-artifacts/, and this script exits non-zero.
set -euo pipefail
build=$1
seconds=$2
runs=${3:-0}
root="$(cd "$(dirname "$0")/.." && pwd)"
seeds="$build/fuzz-seeds"
rm -rf "$seeds"
mkdir -p "$seeds/case_reader" "$seeds/stl" "$build/fuzz-artifacts"
n=0
while IFS= read -r -d '' f; do
    n=$((n + 1))
    cp "$f" "$seeds/case_reader/case_$n.toml"
done < <(find "$root/cases" -name '*.toml' -print0 | sort -z)
# Overrides: a valid one, one that names no key, one with a bad value.
first="$(find "$root/cases" -name 'case.toml' | sort | head -1)"
{ cat "$first"; printf '\n#--set\ntime.end=1e-3\n'; } > "$seeds/case_reader/set_valid.toml"
{ cat "$first"; printf '\n#--set\ntime.ned=1e-3\n'; } > "$seeds/case_reader/set_unknown.toml"
{ cat "$first"; printf '\n#--set\nnumerics.particle_spacing=-1\n'; } > "$seeds/case_reader/set_bad_value.toml"
n=0
while IFS= read -r -d '' f; do
    n=$((n + 1))
    cp "$f" "$seeds/stl/mesh_$n.stl"
done < <(find "$root/cases" -name '*.stl' -size -200k -print0 | sort -z)

status=0
for target in case_reader stl; do
    corpus="$build/fuzz-corpus/$target"
    mkdir -p "$corpus"
    args=(-timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1
          "-artifact_prefix=$build/fuzz-artifacts/${target}-")
    if [[ $seconds -gt 0 ]]; then
        args+=("-max_total_time=$seconds")
    else
        args+=("-runs=$runs" -seed=1)
    fi
    echo "fuzz: $target (${seconds}s, runs $runs)"
    if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        "$build/fuzz/grit_fuzz_$target" "${args[@]}" "$corpus" "$seeds/$target" "$root/fuzz/regressions/$target" \
        2>"$build/fuzz-$target.log"; then
        echo "fuzz: $target FOUND A PROBLEM (log: $build/fuzz-$target.log; input in $build/fuzz-artifacts/)"
        tail -30 "$build/fuzz-$target.log"
        status=1
    else
        grep -E "stat::number_of_executed_units|cov:" "$build/fuzz-$target.log" | tail -2
    fi
done
exit $status

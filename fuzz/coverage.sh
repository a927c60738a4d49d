#!/usr/bin/env bash
# Line coverage of the readers by the fuzz corpus (make fuzz-coverage): the targets built again with
# clang's source-based coverage, each replaying its seeds and the corpus `make fuzz` grew, then
# llvm-cov's report for the reader's own sources.
#   bash fuzz/coverage.sh COVERAGE_BUILD FUZZ_BUILD
set -euo pipefail
build=$1
fuzz_build=$2
root="$(cd "$(dirname "$0")/.." && pwd)"
report() {
    local target=$1
    shift
    local profiles="$build/profiles/$target"
    rm -rf "$profiles"
    mkdir -p "$profiles" "$fuzz_build/fuzz-corpus/$target"
    LLVM_PROFILE_FILE="$profiles/%p.profraw" ASAN_OPTIONS=detect_leaks=0 \
        "$build/fuzz/grit_fuzz_$target" -runs=0 "$fuzz_build/fuzz-corpus/$target" "$fuzz_build/fuzz-seeds/$target" \
        "$root/fuzz/regressions/$target" \
        >"$build/coverage-$target.log" 2>&1
    llvm-profdata-14 merge -sparse "$profiles"/*.profraw -o "$profiles/merged.profdata"
    echo "coverage: $target"
    # The line columns of llvm-cov's report: file, lines, missed lines, line coverage.
    llvm-cov-14 report "$build/fuzz/grit_fuzz_$target" -instr-profile="$profiles/merged.profdata" "$@" |
        awk '/\.(cpp|hpp) / || /^TOTAL/ { n = split($1, p, "/"); printf "  %-24s %6s lines %5s missed %8s\n", p[n], $8, $9, $10 }'
}
report case_reader "$root/src/grit/io/case_reader.cpp" "$root/src/grit/io/case_section.cpp" \
    "$root/src/grit/io/case_tables.cpp" "$root/src/grit/io/shape_reader.cpp" "$root/src/grit/io/material_tables.cpp" \
    "$root/src/grit/io/jet_builder.cpp" "$root/src/grit/modules/probes_table.cpp" "$root/src/grit/modules/cracks_table.cpp"
report stl "$root/src/grit/mesh/stl_file.cpp"

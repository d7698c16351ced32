#!/usr/bin/env bash
# Runs every fuzz target (tests/fuzz/fuzz_*.cpp) with libFuzzer for SECONDS each and prints a
# table: target, executions, corpus size, findings.
#
#   tools/fuzz.sh [--no-build] [--log FILE] SECONDS [TARGET...]
#   e.g. tools/fuzz.sh 60, tools/fuzz.sh 600 vabus eds, tools/fuzz.sh --log ~/fuzz.log 3600
#
# --no-build uses the programs already in build-fuzz/ (while another build runs there);
# --log FILE appends one line per target and run: date, target, seconds, executions, corpus
# size, findings (the totals over many runs are then a sum over that file).
# Builds with clang (CXX, else clang++-16) in build-fuzz/ with AddressSanitizer and
# UndefinedBehaviorSanitizer. Each target starts from its seed corpus in tests/fuzz/corpus/ and
# keeps what it finds in build-fuzz/corpus/<target>/ (not in the repository); a crash, leak,
# timeout or sanitizer report is saved in build-fuzz/findings/<target>/ and counted as a finding,
# and the target is started again for the rest of its time (at most 6 runs per target).
# To keep a finding as a regression input, copy it into tests/fuzz/corpus/<target>/ once fixed.
# Exit status 1 when any target had a finding.
set -euo pipefail

build_first=1
logfile=
while [[ $# -gt 0 && $1 == --* ]]; do
    case $1 in
    --no-build) build_first=0 ;;
    --log)
        logfile=${2:-}
        shift
        ;;
    *) break ;;
    esac
    shift
done
if [[ $# -lt 1 || ! $1 =~ ^[0-9]+$ ]]; then
    sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
fi
seconds=$1
shift

root=$(cd "$(dirname "$0")/.." && pwd)
build=${DRIVEBENCH_FUZZ_BUILD:-$root/build-fuzz}
cxx=${CXX:-clang++-16}
if ! command -v "$cxx" >/dev/null; then
    echo "fuzz.sh: $cxx not found (Debian 12: apt-get install clang-16 libclang-rt-16-dev)" >&2
    exit 2
fi

targets=("$@")
if [[ ${#targets[@]} -eq 0 ]]; then
    for f in "$root"/tests/fuzz/fuzz_*.cpp; do
        n=$(basename "$f" .cpp)
        targets+=("${n#fuzz_}")
    done
fi

if [[ ! -f $build/build.ninja ]]; then
    mkdir -p "$build"
    # -O1 and line tables only, as libFuzzer's own documentation builds: a third of the
    # compile time of -O2 -g, with file:line in every report.
    CXX=$cxx cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" -DDRIVEBENCH_FUZZ=ON -DDRIVEBENCH_SANITIZE=address,undefined \
        -DDRIVEBENCH_BUILD_BENCH=OFF >"$build/configure.log" 2>&1 ||
        { cat "$build/configure.log" >&2; exit 2; }
fi
[[ $build_first -eq 0 ]] || ninja -C "$build" "${targets[@]/#/fuzz_}" >/dev/null

export QT_QPA_PLATFORM=offscreen DRIVEBENCH_LANG=en
# Allocation stacks are not recorded while fuzzing: recording them took a third of the time.
# A finding is then reported without the stack of the allocation involved; replay its input
# with the target and ASAN_OPTIONS=detect_leaks=1 for the whole report.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:malloc_context_size=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

printf '%-16s %14s %8s %9s\n' target executions corpus findings
# The longest input worth trying: the streamed protocols (frames, SLCAN, VABus) meet every
# state and limit of theirs within a few hundred bytes (SLCAN lines end at 64 bytes, a VABus
# telegram at 105, a CAN frame at 8): 1 kB holds nine whole telegrams or sixteen SLCAN lines
# with garbage between them; longer inputs only repeat frames and slow each run down (4 kB
# inputs ran VABus at less than half the rate, with the same coverage).
# RefGo answers may be up to 64 kB (its framer's limit): 68 kB inputs (a length byte per piece
# of up to 64 bytes) can pass it. Files keep 64 kB.
max_len() {
    case $1 in
    slcan | vabus | nm17x | framedecoder | text) echo 1024 ;;
    sdoclient | canopennode) echo 4096 ;; # an SDO block of 127 segments is over 1 kB
    refgo) echo 69632 ;;
    *) echo 65536 ;;
    esac
}

fork_mode() {
    case $1 in
    slcan | framedecoder) echo yes ;;
    *) echo no ;;
    esac
}

status=0
for t in "${targets[@]}"; do
    corpus=$build/corpus/$t
    findings=$build/findings/$t
    log=$build/logs/$t.log
    mkdir -p "$corpus" "$findings" "$(dirname "$log")"
    dict=()
    [[ -f $root/tests/fuzz/dict/$t.dict ]] && dict=(-dict="$root/tests/fuzz/dict/$t.dict")
    before=$(find "$findings" -type f | wc -l)
    : >"$log"
    # Most targets fuzz in one process for the whole time: libFuzzer's -fork mode first
    # replays the whole corpus and then starts a process for every job of 1, 2, 3... seconds,
    # which cost more than the fuzzing for the targets whose inputs take milliseconds (EDS, the
    # simulated node, texts). A finding ends that process, so it is started again (from the
    # grown corpus) for the time left. The fastest targets (microseconds per input) run 1.3
    # to 2.3 times as many inputs in -fork mode, whose jobs each mutate a few recent inputs.
    end=$((SECONDS + seconds))
    runs=0
    mode=()
    [[ $(fork_mode "$t") == no ]] ||
        mode=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
    while left=$((end - SECONDS)) && [[ $left -gt 0 && $runs -lt 6 ]]; do
        runs=$((runs + 1))
        "$build/tests/fuzz/fuzz_$t" "$corpus" "$root/tests/fuzz/corpus/$t" "${dict[@]}" \
            -max_total_time="$left" -timeout=10 -rss_limit_mb=2048 -max_len="$(max_len "$t")" \
            "${mode[@]}" -reload=0 -artifact_prefix="$findings/" -print_final_stats=1 \
            >>"$log" 2>&1 && break
        [[ ${#mode[@]} -eq 0 ]] || break
    done
    execs=$(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | awk '{s+=$2} END {print s+0}' || true)
    if [[ $execs -eq 0 ]]; then
        execs=$( (grep -Eo '^#[0-9]+' "$log" || true) | tail -1 | tr -d '#')
    fi
    size=$(find "$corpus" -type f | wc -l)
    found=$(( $(find "$findings" -type f | wc -l) - before ))
    printf '%-16s %14s %8s %9s\n' "$t" "${execs:-0}" "$size" "$found"
    [[ -z $logfile ]] || printf '%s %-16s %6s %12s %7s %3s\n' "$(date -u +%FT%TZ)" "$t" "$seconds" \
        "${execs:-0}" "$size" "$found" >>"$logfile"
    [[ $found -eq 0 ]] || status=1
done
exit $status

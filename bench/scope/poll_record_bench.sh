#!/usr/bin/env bash
# Fixed-rate host polling through `drivebench-cli record`: lost samples, interval error and
# recording length, at 1 and 2 ms with 2 and 8 objects, over RefGo and CANopen (SLCAN over TCP).
#
# Without --uri it starts `drivebench-sim movingcap` on loopback with OS-chosen ports and records
# from both of its doors; with --uri (repeatable) it records from those devices instead (they
# need the objects below). Each case runs --runs times; the table gives the median of the runs
# and, in brackets, their spread (min..max).
#   lost %     lost samples / (recorded + lost)
#   p50, p99   |interval between two samples of one object - period|, in % of the period
#              (an interval across a lost sample counts with its full error)
#   length ms  how long the recording lasted (--duration asks for a whole number of seconds)
# A first line per link gives its capacity: reads/s of one object at --rate-ms 0.
# --rt runs the recorder (and the simulator it starts) with real-time priority (chrt -f 20, as
# root): on a machine busy with other work this stands in for an idle one.
#
#   bench/scope/poll_record_bench.sh [--build DIR] [--cli PATH] [--sim PATH] [--uri URI]...
#                                    [--runs N] [--duration S] [--rates "1 2"]
#                                    [--objects "2 8"] [--obj-list "I:S ..."] [--rt]
# --obj-list names the objects to record (the first N of them for N objects); the default is
# 6064:0 6078:0 606C:0 6041:0 6061:0 607A:0 6081:0 6083:0, which a CiA 402 drive has. For an
# ACTIVE Cube over VABus, e.g. --obj-list "210:0 211:0 213:0 240:0" --objects "2 4".
set -euo pipefail

build=build
cli=
sim=
uris=()
runs=5
duration=3
rates="1 2"
counts="2 8"
rt=()
objects=(6064:0 6078:0 606C:0 6041:0 6061:0 607A:0 6081:0 6083:0)

while (($#)); do
    case "$1" in
    --build) build=$2; shift 2 ;;
    --cli) cli=$2; shift 2 ;;
    --sim) sim=$2; shift 2 ;;
    --uri) uris+=("$2"); shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --duration) duration=$2; shift 2 ;;
    --rates) rates=$2; shift 2 ;;
    --objects) counts=$2; shift 2 ;;
    --obj-list) read -r -a objects <<<"$2"; shift 2 ;;
    --rt) rt=(chrt -f 20); shift ;;
    -h | --help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "poll_record_bench: unknown option $1 (see --help)" >&2; exit 2 ;;
    esac
done
cli=${cli:-$build/app/drivebench-cli}
sim=${sim:-$build/app/drivebench-sim}
[[ -x $cli ]] || { echo "poll_record_bench: no drivebench-cli at $cli (--build or --cli)" >&2; exit 2; }

work=$(mktemp -d)
sim_pid=
cleanup() {
    [[ -n $sim_pid ]] && kill "$sim_pid" 2>/dev/null && wait "$sim_pid" 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT

if ((${#uris[@]} == 0)); then
    [[ -x $sim ]] || { echo "poll_record_bench: no drivebench-sim at $sim (--build or --sim)" >&2; exit 2; }
    "${rt[@]}" "$sim" movingcap --refgo-port 0 --slcan-port 0 >"$work/sim.log" 2>&1 &
    sim_pid=$!
    for _ in $(seq 100); do
        (($(grep -c 'listening on 127.0.0.1:' "$work/sim.log") >= 2)) && break
        sleep 0.1
    done
    mapfile -t uris < <(sed -n 's/.*listening on 127\.0\.0\.1:[0-9]* (\(.*\))$/\1/p' "$work/sim.log")
    ((${#uris[@]} == 2)) || { echo "poll_record_bench: the simulator did not start:" >&2; cat "$work/sim.log" >&2; exit 1; }
fi

# One run: prints "lost% p50% p99% length_ms" (the CLI exits 1 when samples were lost).
run_once() {
    local uri=$1 rate=$2 n=$3 csv=$work/run.csv args=()
    for o in "${objects[@]:0:n}"; do args+=(--obj "$o"); done
    local out
    out=$("${rt[@]}" "$cli" record "$uri" "${args[@]}" --rate-ms "$rate" --duration "$duration" -o "$csv" 2>/dev/null) || true
    # "recorded N samples of K objects over T s[, L lost] -> FILE"
    local samples seconds lost
    samples=$(sed -n 's/^recorded \([0-9]*\) samples.*/\1/p' <<<"$out")
    seconds=$(sed -n 's/.* over \([0-9.]*\) s.*/\1/p' <<<"$out")
    lost=$(sed -n 's/.* s, \([0-9]*\) lost.*/\1/p' <<<"$out")
    [[ -n $samples ]] || { echo "poll_record_bench: record failed: $out" >&2; exit 1; }
    awk -F, -v period="$rate" '
        /^#/ || /^time_s/ { next }
        { for (i = 2; i <= NF; ++i) if ($i != "") {
              if (i in last) { d = ($1 - last[i]) * 1000 - period; if (d < 0) d = -d; print d / period * 100 }
              last[i] = $1 } }' "$csv" | sort -g >"$work/err"
    local count p50 p99
    count=$(wc -l <"$work/err")
    p50=$(sed -n "$(((count * 50 + 99) / 100))p" "$work/err")
    p99=$(sed -n "$(((count * 99 + 99) / 100))p" "$work/err")
    awk -v s="$samples" -v l="${lost:-0}" -v p50="$p50" -v p99="$p99" -v t="$seconds" \
        'BEGIN { printf "%.3f %.1f %.1f %.0f\n", 100 * l / (s + l), p50, p99, t * 1000 }'
}

# Median and spread of column $1 of the lines on stdin: "median (min..max)".
summary() {
    sort -g -k"$1","$1" | awk -v c="$1" '{ v[NR] = $c } END {
        m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
        printf "%s (%s..%s)", m, v[1], v[NR] }'
}

echo "poll_record_bench: $runs runs of ${duration} s per case; median (min..max); $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)${rt:+; real-time priority}"
printf '%-50s %5s %4s  %-24s %-24s %-24s %s\n' link rate objs "lost %" "p50 err %" "p99 err %" "length ms"
for uri in "${uris[@]}"; do
    cap=$("${rt[@]}" "$cli" record "$uri" --obj "${objects[0]}" --rate-ms 0 --duration 1 -o "$work/cap.csv" 2>/dev/null |
        sed -n 's/^recorded \([0-9]*\) samples.* over \([0-9.]*\) s.*/\1 \2/p' | awk '{ printf "%.0f", $1 / $2 }')
    echo "$uri: capacity ${cap:-?} reads/s"
    for rate in $rates; do
        for n in $counts; do
            : >"$work/runs"
            for _ in $(seq "$runs"); do run_once "$uri" "$rate" "$n" >>"$work/runs"; done
            printf '%-50s %3s ms %4s  %-24s %-24s %-24s %s\n' "$uri" "$rate" "$n" \
                "$(summary 1 <"$work/runs")" "$(summary 2 <"$work/runs")" \
                "$(summary 3 <"$work/runs")" "$(summary 4 <"$work/runs")"
        done
    done
done

#!/usr/bin/env bash
# Round trips/s of our engine against those of the smallest client we can write (plain C++ and
# POSIX sockets, bench/minimal), on the same link to the same device, measured side by side,
# with a third client between them: the same exchange on Qt's event loop with no protocol code
# (qtloop_minimal), the floor of any engine built on that loop. The three run in turn (the
# order rotated every run, so drift of a shared machine's load hits all alike), --runs times
# each.
#   RefGo:  refgo_minimal  qtloop_minimal  refgo_bench --engine-only          (RefgoClient::objectRead)
#   SDO:    sdo_minimal    qtloop_minimal  canopen_sdo_bench --expedited-only (SdoClient expedited upload)
# Without --uri it starts `drivebench-sim movingcap` on loopback (OS-chosen ports) and measures
# both of its doors; with --uri (repeatable: refgo://HOST:PORT, canopen+slcan://HOST:PORT?node=N)
# those devices instead. Prints per link the median (min..max) of each side and of the per-run
# ratio engine/minimal (the goal is >= 0.90), and each client's own CPU time per round trip (its
# cost, which the load of a shared machine hardly changes). --rt runs the clients (and the
# simulator it starts) with real-time priority (chrt -f 20, as root): on a machine busy with
# other work this stands in for an idle one. --phases then runs each client once more with
# bench/minimal/libroundtrip_phases.so preloaded and prints where its round trip went (the
# client's own work between answer and request, the write, the wait, the read), per round trip.
#
#   bench/engine_vs_minimal.sh [--build DIR] [--uri URI]... [--runs N] [--count N] [--object I:S]
#                              [--rt] [--phases]
set -euo pipefail

build=build
uris=()
runs=7
count=20000
object=6041:0
rt=()
phases=0

while (($#)); do
    case "$1" in
    --build) build=$2; shift 2 ;;
    --uri) uris+=("$2"); shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --count) count=$2; shift 2 ;;
    --object) object=$2; shift 2 ;;
    --rt) rt=(chrt -f 20); shift ;;
    --phases) phases=1; shift ;;
    -h | --help) sed -n '2,25p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "engine_vs_minimal: unknown option $1 (see --help)" >&2; exit 2 ;;
    esac
done
for tool in app/drivebench-sim bench/minimal/refgo_minimal bench/minimal/sdo_minimal \
    bench/minimal/qtloop_minimal bench/refgo/refgo_bench bench/canopen/canopen_sdo_bench; do
    [[ -x $build/$tool ]] || { echo "engine_vs_minimal: no $build/$tool (--build DIR)" >&2; exit 2; }
done

work=$(mktemp -d)
sim_pid=
cleanup() {
    [[ -n $sim_pid ]] && kill "$sim_pid" 2>/dev/null && wait "$sim_pid" 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT

if ((${#uris[@]} == 0)); then
    : >"$work/sim.log"
    "${rt[@]}" "$build/app/drivebench-sim" movingcap --refgo-port 0 --slcan-port 0 >"$work/sim.log" 2>&1 &
    sim_pid=$!
    for _ in $(seq 100); do
        (($(grep -c 'listening on 127.0.0.1:' "$work/sim.log") >= 2)) && break
        sleep 0.1
    done
    mapfile -t uris < <(sed -n 's/.*listening on 127\.0\.0\.1:[0-9]* (\(.*\))$/\1/p' "$work/sim.log")
    ((${#uris[@]} == 2)) || { echo "engine_vs_minimal: the simulator did not start:" >&2; cat "$work/sim.log" >&2; exit 1; }
fi

# "rate cpu" a benchmark printed ("... = 12345/s, cpu 12.3 us per round trip"), or an error
# naming the command.
measure() {
    local out
    out=$("${rt[@]}" "$@" 2>&1) || { echo "engine_vs_minimal: failed: $*: $out" >&2; exit 1; }
    sed -n 's/.* = \([0-9]*\)\/s, cpu \([0-9.]*\) us.*/\1 \2/p' <<<"$out" | head -1
}

# Median and spread of column $1 of the lines on stdin: "median (min..max)".
summary() {
    sort -g -k"$1","$1" | awk -v c="$1" '{ v[NR] = $c } END {
        m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
        printf "%s (%s..%s)", m, v[1], v[NR] }'
}

echo "engine_vs_minimal: $runs runs in turn of $count round trips each, object $object; median (min..max); $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)${rt:+; real-time priority}"
printf '%-42s %-22s %-22s %-22s %-20s %-20s %-20s %-18s %-18s %s\n' link "minimal /s" "qt loop /s" \
    "engine /s" "engine/minimal" "qt loop/minimal" "engine/qt loop" "minimal cpu us" \
    "qt loop cpu us" "engine cpu us"
for uri in "${uris[@]}"; do
    case "$uri" in
    refgo://*)
        minimal=("$build/bench/minimal/refgo_minimal" --uri "$uri" --count "$count" --object "$object")
        engine=("$build/bench/refgo/refgo_bench" --engine-only --uri "$uri" --count "$count" --object "$object") ;;
    canopen+slcan://*)
        minimal=("$build/bench/minimal/sdo_minimal" --uri "$uri" --count "$count" --object "$object")
        engine=("$build/bench/canopen/canopen_sdo_bench" --expedited-only --uri "$uri" --count "$count" --object "$object") ;;
    *) echo "engine_vs_minimal: no minimal client for $uri" >&2; exit 2 ;;
    esac
    qtloop=("$build/bench/minimal/qtloop_minimal" --uri "$uri" --count "$count" --object "$object")
    : >"$work/runs"
    for i in $(seq "$runs"); do
        case $((i % 3)) in
        1) m=$(measure "${minimal[@]}"); q=$(measure "${qtloop[@]}"); e=$(measure "${engine[@]}") ;;
        2) q=$(measure "${qtloop[@]}"); e=$(measure "${engine[@]}"); m=$(measure "${minimal[@]}") ;;
        0) e=$(measure "${engine[@]}"); m=$(measure "${minimal[@]}"); q=$(measure "${qtloop[@]}") ;;
        esac
        [[ -n $m && -n $q && -n $e ]] || { echo "engine_vs_minimal: no figures from a run on $uri" >&2; exit 1; }
        awk -v m="$m" -v q="$q" -v e="$e" 'BEGIN { split(m, a, " "); split(q, c, " "); split(e, b, " ")
            printf "%d %d %d %.3f %.3f %.3f %.1f %.1f %.1f\n", a[1], c[1], b[1], b[1] / a[1],
                c[1] / a[1], b[1] / c[1], a[2], c[2], b[2] }' >>"$work/runs"
    done
    line=$(printf '%-42s' "$uri")
    for column in 1 2 3; do line+=$(printf ' %-22s' "$(summary $column <"$work/runs")"); done
    for column in 4 5 6; do line+=$(printf ' %-20s' "$(summary $column <"$work/runs")"); done
    for column in 7 8 9; do line+=$(printf ' %-18s' "$(summary $column <"$work/runs")"); done
    echo "$line"
    if ((phases)); then
        for client in minimal qtloop engine; do
            declare -n client_command=$client
            out=$(LD_PRELOAD=$(realpath "$build/bench/minimal/libroundtrip_phases.so") "${rt[@]}" \
                "${client_command[@]}" 2>&1) || { echo "engine_vs_minimal: failed: ${client_command[*]}: $out" >&2; exit 1; }
            printf '  %-8s %s\n' "$client" "$(sed -n 's/^round-trip phases //p' <<<"$out" | tail -1)"
            unset -n client_command
        done
    fi
done

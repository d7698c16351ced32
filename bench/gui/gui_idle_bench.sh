#!/usr/bin/env bash
# CPU use of the GUI while nothing changes on screen: runs `drivebench --demo` under Xvfb
# (1366 x 768), lets it settle, then reads the process's CPU time from /proc/PID/stat over a
# window and prints % of one core, per thread name as well, and the resident memory. Repeats
# --runs times and prints the median and spread. The demo's simulated devices run in a thread of
# their own ("demo devices"): the figures are given for the whole process, for the program
# without that thread (the GUI's own cost) and for that thread alone. Settings go to a temporary
# folder, so the user's layout and recent connections do not change the figure.
#
#   bench/gui/gui_idle_bench.sh [--build DIR | --binary PATH] [--runs N] [--seconds S]
#                               [--settle S] [--rt] [-- EXTRA DRIVEBENCH ARGUMENTS]
set -euo pipefail

build=build
binary=
runs=3
seconds=30
settle=8
rt=()
extra=()
while (($#)); do
    case "$1" in
    --build) build=$2; shift 2 ;;
    --binary) binary=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --settle) settle=$2; shift 2 ;;
    --rt) rt=(chrt -f 20); shift ;;
    --) shift; extra=("$@"); break ;;
    -h | --help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "gui_idle_bench.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    esac
done
binary=${binary:-$build/app/drivebench}
[[ -x $binary ]] || { echo "gui_idle_bench.sh: no $binary (build the target drivebench)" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "gui_idle_bench.sh: needs xvfb-run (package xvfb)" >&2; exit 2; }
tck=$(getconf CLK_TCK)

# ticks PID: utime + stime of the process (fields 14 and 15 after the command name).
ticks() { sed 's/.*) //' "/proc/$1/stat" | awk '{ print $12 + $13 }'; }
# thread_ticks PID: "name ticks" per thread, summed over threads of the same name.
thread_ticks() {
    local t
    for t in /proc/"$1"/task/*; do
        [[ -r $t/stat ]] || continue
        printf '%s %s\n' "$(tr ' ' '_' <"$t/comm")" "$(sed 's/.*) //' "$t/stat" | awk '{ print $12 + $13 }')"
    done | awk '{ s[$1] += $2 } END { for (n in s) print n, s[n] }' | sort
}

results=()
for run in $(seq "$runs"); do
    home=$(mktemp -d)
    pidfile=$home/pid
    HOME=$home XDG_CONFIG_HOME=$home/config XDG_DATA_HOME=$home/data XDG_RUNTIME_DIR=$home \
        "${rt[@]}" xvfb-run -a -s "-screen 0 1366x768x24" \
        sh -c 'echo $$ >"$0"; exec "$@"' "$pidfile" "$binary" --demo "${extra[@]}" \
        >"$home/log.txt" 2>&1 &
    runner=$!
    for _ in $(seq 100); do [[ -s $pidfile ]] && break; sleep 0.1; done
    pid=$(cat "$pidfile")
    sleep "$settle"
    if ! kill -0 "$pid" 2>/dev/null; then
        echo "gui_idle_bench.sh: drivebench ended early:" >&2
        cat "$home/log.txt" >&2
        exit 1
    fi
    before=$(ticks "$pid")
    thread_ticks "$pid" >"$home/threads.before"
    sleep "$seconds"
    after=$(ticks "$pid")
    thread_ticks "$pid" >"$home/threads.after"
    rss=$(awk '/^VmRSS/ { print $2 / 1024 }' "/proc/$pid/status")
    kill "$pid"
    wait "$runner" 2>/dev/null || true
    cpu=$(awk -v a="$before" -v b="$after" -v s="$seconds" -v t="$tck" 'BEGIN { printf "%.2f", 100 * (b - a) / (s * t) }')
    devices=$(join -a2 -e0 -o 0,1.2,2.2 "$home/threads.before" "$home/threads.after" |
        awk -v s="$seconds" -v t="$tck" '$1 == "demo_devices" { d = $3 - $2 } END { printf "%.2f", 100 * d / (s * t) }')
    gui=$(awk -v c="$cpu" -v d="$devices" 'BEGIN { printf "%.2f", c - d }')
    printf 'run %d: %s %% of a core (GUI %s %%, demo devices %s %%), %.0f MB resident; threads:' \
        "$run" "$cpu" "$gui" "$devices" "$rss"
    join -a2 -e0 -o 0,1.2,2.2 "$home/threads.before" "$home/threads.after" |
        awk -v s="$seconds" -v t="$tck" '{ d = $3 - $2; if (d > 0) printf " %s %.2f %%", $1, 100 * d / (s * t) }'
    echo
    results+=("$cpu $rss $gui $devices")
    rm -rf "$home"
done
printf '%s\n' "${results[@]}" | awk -v n="$runs" -v s="$seconds" '
    { for (k = 1; k <= 4; ++k) v[k, NR] = $k }
    function sort(k,   a, b, t) {
        for (a = 1; a <= NR; ++a) for (b = a + 1; b <= NR; ++b)
            if (v[k, b] < v[k, a]) { t = v[k, a]; v[k, a] = v[k, b]; v[k, b] = t } }
    function med(k) { return NR % 2 ? v[k, (NR + 1) / 2] : (v[k, NR / 2] + v[k, NR / 2 + 1]) / 2 }
    END {
        for (k = 1; k <= 4; ++k) sort(k)
        printf "idle CPU (%d runs of %d s): median %.2f %% of a core (%.2f..%.2f)\n", NR, s, med(1), v[1, 1], v[1, NR]
        printf "idle CPU of the GUI without the demo devices: median %.2f %% of a core (%.2f..%.2f)\n", med(3), v[3, 1], v[3, NR]
        printf "idle CPU of the demo devices thread: median %.2f %% of a core (%.2f..%.2f)\n", med(4), v[4, 1], v[4, NR]
        printf "resident memory: median %.0f MB (%.0f..%.0f)\n", med(2), v[2, 1], v[2, NR] }'

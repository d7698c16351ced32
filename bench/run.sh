#!/usr/bin/env bash
# Runs every benchmark of bench/ with modest defaults and prints one table of figures
# (benchmark, figure, median, spread min..max, unit) so that a later change can be compared with
# this one side by side. Each benchmark also gets its process's CPU use (% of one core over its
# run) and peak memory (max RSS) from /usr/bin/time. The full outputs go to a folder it names
# (default bench-results/DATE-TIME).
#
# Without --uri the benchmarks that talk to a device use the simulators (in their own process or
# drivebench-sim); with --uri (repeatable) they measure those devices instead, each benchmark the
# URIs of its protocol (refgo://, canopen+slcan://, canopen+socketcan://..., vabus://); the
# device-free ones (scope plot, Morse, node scan) run as usual. --quick finishes in under a
# minute (fewer and shorter runs, the scope plot at 8 x 1e6 only, no record-based polling). --rt
# runs the round-trip comparison, the record-based polling and the scope plot with real-time
# priority (chrt, as root): on a machine busy with other work their figures then stand in for
# an idle machine's. A benchmark that is not built yet is built first (ninja in --build).
# The full run also measures the GUI idle with the demo (bench/gui/gui_idle_bench.sh, needs
# xvfb-run and the target drivebench).
#
#   bench/run.sh [--build DIR] [--uri URI]... [--runs N] [--quick] [--rt] [--out DIR]
set -euo pipefail

build=build
uris=()
runs=3
quick=0
out=
rt=()
here=$(cd "$(dirname "$0")" && pwd)

while (($#)); do
    case "$1" in
    --build) build=$2; shift 2 ;;
    --uri) uris+=("$2"); shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    --rt) rt=(--rt); shift ;;
    --out) out=$2; shift 2 ;;
    -h | --help) sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "run.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    esac
done
[[ -x /usr/bin/time ]] || { echo "run.sh: needs /usr/bin/time (Debian package time)" >&2; exit 2; }
out=${out:-bench-results/$(date +%Y%m%d-%H%M%S)}
mkdir -p "$out"
figures=$out/figures.txt # benchmark|figure|value|unit or benchmark|figure|median|min|max|unit
: >"$figures"

# URIs of the given schemes (a regular expression), one per line.
uris_of() {
    local u
    for u in "${uris[@]}"; do [[ $u =~ ^($1) ]] && echo "$u"; done
    return 0
}

# bench NAME RUNS EXTRACTOR COMMAND...: runs COMMAND RUNS times (output in $out/NAME.N.txt) and
# appends the figures EXTRACTOR (an awk program) finds in each output, plus CPU % and max RSS.
bench() {
    local name=$1 n=$2 extract=$3 i
    shift 3
    if [[ ! -x $1 && $1 == "$build"/bench/* && -f $build/build.ninja ]]; then
        # A benchmark that was not built yet (e.g. a tree built for tests only): build it.
        echo "run.sh: building $(basename "$1") ..." >&2
        nice ninja -C "$build" "$(basename "$1")" >"$out/$name.build.txt" 2>&1 || true
    fi
    if [[ ! -x $1 ]]; then
        echo "run.sh: $name skipped: no $1 (see $out/$name.build.txt)" >&2
        echo "$name|skipped (cannot be built, see $out/$name.build.txt)|-|-" >>"$figures"
        return 0
    fi
    printf 'run.sh: %s (%d runs) ...\n' "$name" "$n" >&2
    for i in $(seq "$n"); do
        local log=$out/$name.$i.txt
        if ! /usr/bin/time -f 'TIME %e %P %M' -o "$log.time" "$@" >"$log" 2>&1; then
            echo "run.sh: $name failed (see $log)" >&2
            echo "$name|FAILED (see $log)|-|-" >>"$figures"
            return 0
        fi
        awk -v b="$name" "$extract" "$log" >>"$figures"
        awk -v b="$name" '{ sub(/%/, "", $3); printf "%s|wall time|%s|s\n%s|CPU|%s|%% of a core\n%s|memory|%.1f|MB max RSS\n", b, $2, b, $3, b, $4 / 1024 }' "$log.time" >>"$figures"
    done
}

if ((quick)); then
    runs=3 count=3000 pairs=3 seconds=0.3 repeat=3 reads=500 size=20000
else
    count=20000 pairs=7 seconds=2 repeat=5 reads=2000 size=102400
fi

# ---- engine against the minimal client (its own alternating runs, medians and spread) ----
evm=(--build "$build" --runs "$pairs" --count "$count" "${rt[@]}")
while read -r u; do [[ -n $u ]] && evm+=(--uri "$u"); done < <(uris_of 'refgo://|canopen\+slcan://')
if ((${#uris[@]} == 0 || ${#evm[@]} > 6 + ${#rt[@]})); then
    bench engine_vs_minimal 1 '
        $1 ~ /^refgo:/ { p = "RefGo" } $1 ~ /^canopen/ { p = "SDO" }
        $1 ~ /:\/\// { gsub(/[()]/, ""); split($3, a, /\.\./); split($5, q, /\.\./); split($7, e, /\.\./)
            split($9, r, /\.\./); split($11, f, /\.\./); split($13, g, /\.\./)
            print b "|" p " minimal client|" $2 "|" a[1] "|" a[2] "|round trips/s"
            print b "|" p " Qt loop client|" $4 "|" q[1] "|" q[2] "|round trips/s"
            print b "|" p " engine|" $6 "|" e[1] "|" e[2] "|round trips/s"
            print b "|" p " engine/minimal|" $8 "|" r[1] "|" r[2] "|ratio"
            print b "|" p " Qt loop/minimal|" $10 "|" f[1] "|" f[2] "|ratio"
            print b "|" p " engine/Qt loop|" $12 "|" g[1] "|" g[2] "|ratio" }' \
        "$here/engine_vs_minimal.sh" "${evm[@]}"
fi

# ---- protocol engines ----
sdo_extract='
    /^expedited upload/ { for (i = 1; i <= NF; ++i) if ($i == "=") { v = $(i + 1); sub(/\/s,?/, "", v) }
        print b "|expedited upload|" v "|round trips/s" }
    /^  latency/ { print b "|expedited p99 latency|" $8 "|ms" }
    /download|upload  / && /kB\/s/ { for (i = 1; i <= NF; ++i) if ($i == "=") v = $(i + 1)
        print b "|" $1 " " $2 "|" v "|kB/s" }'
refgo_extract='
    / round trips in / { for (i = 1; i <= NF; ++i) if ($i == "=") { v = $(i + 1); sub(/\/s,?/, "", v) }
        name = $1 " " $2; print b "|" name "|" v "|round trips/s" }'
if ((${#uris[@]} == 0)); then
    bench canopen_sdo_bench "$runs" "$sdo_extract" "$build/bench/canopen/canopen_sdo_bench" --count "$count" --size "$size"
    bench refgo_bench "$runs" "$refgo_extract" "$build/bench/refgo/refgo_bench" --count "$count"
else
    while read -r u; do
        [[ -n $u ]] && bench "canopen_sdo_bench $u" "$runs" "$sdo_extract" "$build/bench/canopen/canopen_sdo_bench" --uri "$u" --count "$count" --object 1000:0
    done < <(uris_of 'canopen\+')
    while read -r u; do
        [[ -n $u ]] && bench "refgo_bench $u" "$runs" "$refgo_extract" "$build/bench/refgo/refgo_bench" --uri "$u" --count "$count"
    done < <(uris_of 'refgo://')
fi
((${#uris[@]})) || bench canopen_scan_bench 1 '
    /^  run/ { for (i = 1; i <= NF; ++i) if ($i == "ms" && $(i + 1) == "total") print b "|scan 1..127|" $(i - 1) "|ms" }' \
    "$build/bench/canopen/canopen_scan_bench" --repeat "$repeat"

# ---- parameters ----
backup=("$build/bench/params/params_backup_bench" --repeat "$repeat")
while read -r u; do [[ -n $u ]] && backup+=(--uri "$u"); done < <(uris_of 'refgo://|canopen\+')
if ((${#uris[@]} == 0 || ${#backup[@]} > 3)); then
    bench params_backup_bench 1 '
        / median / { for (i = 1; i <= NF; ++i) { if ($i == "objects") { split($0, h, /  +/); name = h[1] }
            if ($i == "median") m = $(i + 1); if ($i == "min") lo = $(i + 1); if ($i == "max") hi = $(i + 1) }
            print b "|backup " name "|" m "|" lo "|" hi "|ms" }' "${backup[@]}"
fi
vabus=("$build/bench/vabus/vabus_bench" --repeat "$repeat" --reads "$reads")
vabus_extract='
    /^reads of/ { print b "|reads|" $8 "|" $11 "|" $13 "|reads/s" }
    /^full backup/ { print b "|full backup|" $6 "|" $9 "|" $11 "|ms" }'
if ((${#uris[@]} == 0)); then
    bench vabus_bench 1 "$vabus_extract" "${vabus[@]}"
else
    while read -r u; do
        [[ -n $u ]] && bench "vabus_bench $u" 1 "$vabus_extract" "${vabus[@]}" --uri "$u"
    done < <(uris_of 'vabus://')
fi

# ---- scope ----
poll=("$build/bench/scope/scope_poll_bench" --seconds "$seconds")
while read -r u; do [[ -n $u ]] && poll+=(--uri "$u"); done < <(uris_of 'refgo://|canopen\+')
if ((${#uris[@]} == 0 || ${#poll[@]} > 3)); then
    bench scope_poll_bench "$runs" '
        NR > 1 && NF == 7 { print b "|" $1 " " $2 " obj " $3 " " $4 "|" $5 "|samples/s"
            print b "|" $1 " " $2 " obj " $3 " " $4 " lost|" $7 "|samples" }
        NR > 1 && NF == 6 { print b "|" $1 " " $2 " obj " $3 "|" $4 "|samples/s"
            print b "|" $1 " " $2 " obj " $3 " lost|" $6 "|samples" }' "${poll[@]}"
fi
if ((!quick)); then
    record=("$here/scope/poll_record_bench.sh" --build "$build" --runs "$runs" --duration 1 "${rt[@]}")
    while read -r u; do [[ -n $u ]] && record+=(--uri "$u"); done < <(uris_of 'refgo://|canopen\+')
    if ((${#uris[@]} == 0 || ${#record[@]} > 7 + ${#rt[@]})); then
        bench poll_record_bench 1 '
            / capacity [0-9]+ reads/ { link = $1; sub(/:\/\/.*/, "", link); print b "|" link " capacity|" $3 "|reads/s" }
            $3 == "ms" { gsub(/[()]/, ""); split($6, l, /\.\./); split($10, p, /\.\./)
                link = $1; sub(/:\/\/.*/, "", link); c = link " " $2 " ms " $4 " obj"
                print b "|" c " lost|" $5 "|" l[1] "|" l[2] "|%"
                print b "|" c " p99 interval error|" $9 "|" p[1] "|" p[2] "|% of period" }' \
            "${record[@]}"
    fi
fi
# Frame time (wall clock and CPU time of the frame) at 8 x 1e6, 8 x 1e7 and 1 x 1e7 samples,
# against a bare QCustomPlot, and the CPU cost of recording 8 x 2.5 kHz.
plot_extract='
    $5 == "frame" && $10 == "fps" { c = $1 " " $2 " " $3 " " $4
        print b "|" c "|" $9 "|fps"; print b "|" c " (CPU time)|" $16 "|fps" }
    /^append: / { sub(/^append: /, ""); v = $(NF - 4); sub(/ [0-9.-]+ % of a core$/, "")
        print b "|append 8 x 2.5 kHz: " $0 "|" v "|% of a core" }'
if ((quick)); then
    QT_QPA_PLATFORM=offscreen bench scope_plot_bench 1 "$plot_extract" \
        "$build/bench/scope/scope_plot_bench" 30 --cases 8x1e6 --append-seconds 1 "${rt[@]}"
else
    QT_QPA_PLATFORM=offscreen bench scope_plot_bench "$runs" "$plot_extract" \
        "$build/bench/scope/scope_plot_bench" 60 --append-seconds 3 "${rt[@]}"
fi

# ---- GUI idle cost: the demo under Xvfb, nothing changing on screen ----
if ((${#uris[@]} == 0 && !quick)) && command -v xvfb-run >/dev/null; then
    # The demo's devices run in a thread of their own: the GUI's own cost is the process
    # without that thread.
    bench gui_idle_bench 1 '
        function figure(name, unit,   i, r) { gsub(/[()]/, ""); for (i = 1; i < NF; ++i) if ($i == "median") m = $(i + 1)
            split($NF, r, /\.\./); print b "|" name "|" m "|" r[1] "|" r[2] "|" unit }
        /^idle CPU \(/ { figure("idle CPU, demo: whole process", "% of a core") }
        /^idle CPU of the GUI/ { figure("idle CPU, demo: GUI without the demo devices", "% of a core") }
        /^idle CPU of the demo devices/ { figure("idle CPU, demo: the demo devices thread", "% of a core") }
        /^resident memory/ { figure("resident memory, demo", "MB") }' \
        "$here/gui/gui_idle_bench.sh" --build "$build" --runs "$runs" --seconds 30
fi

# ---- Morse ----
if ((${#uris[@]} == 0)); then
    bench morse_stream 1 'BEGIN {}' "$build/bench/morse/morse_stream" 3 "$((quick ? 3 : 12))"
    ((quick)) || bench morse_corpus 1 'BEGIN {}' "$build/bench/morse/morse_corpus" 10 7
fi

# ---- the table ----
{
    echo "bench/run.sh $(date '+%F %T'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), runs $runs$( ((quick)) && echo ', quick')${rt:+, real-time priority}${uris[*]:+, uri ${uris[*]}}"
    awk -F'|' '
        NF == 4 { key = $1 SUBSEP $2; if (!(key in unit)) order[++n] = key; unit[key] = $4; vals[key] = vals[key] " " $3 }
        NF == 6 { key = $1 SUBSEP $2; if (!(key in unit)) order[++n] = key; unit[key] = $6; fixed[key] = $3 "|" $4 ".." $5 }
        END {
            printf "%-44s %-42s %12s  %-22s %s\n", "benchmark", "figure", "median", "spread", "unit"
            for (i = 1; i <= n; ++i) {
                key = order[i]; split(key, k, SUBSEP)
                if (key in fixed) { split(fixed[key], f, "|"); med = f[1]; spread = f[2] }
                else {
                    m = split(substr(vals[key], 2), v, " ")
                    if (v[1] == "-") { med = "-"; spread = "" }
                    else {
                        for (a = 1; a <= m; ++a) for (c = a + 1; c <= m; ++c) if (v[c] + 0 < v[a] + 0) { t = v[a]; v[a] = v[c]; v[c] = t }
                        med = m % 2 ? v[(m + 1) / 2] : (v[m / 2] + v[m / 2 + 1]) / 2
                        spread = m > 1 ? v[1] ".." v[m] : "(1 run)"
                    }
                }
                printf "%-44s %-42s %12s  %-22s %s\n", k[1], k[2], med, spread, unit[key]
            }
        }' "$figures"
    # The performance goals, each from the figures above: the figure, the target, met or not.
    echo
    awk -F'|' '
        function med(key,   m, v, a, c, t) {
            if (key in fixed) { split(fixed[key], v, "|"); return v[1] }
            m = split(substr(vals[key], 2), v, " ")
            for (a = 1; a <= m; ++a) for (c = a + 1; c <= m; ++c) if (v[c] + 0 < v[a] + 0) { t = v[a]; v[a] = v[c]; v[c] = t }
            return m % 2 ? v[(m + 1) / 2] : (v[m / 2] + v[m / 2 + 1]) / 2 }
        function goal(name, figure, target, ok) {
            printf "%-30s %-46s %-22s %s\n", name, figure, target, figure == "-" ? "not measured" : ok ? "met" : "NOT MET" }
        NF == 4 && $3 != "-" { key = $1 SUBSEP $2; vals[key] = vals[key] " " $3; keys[key] = 1 }
        NF == 6 { key = $1 SUBSEP $2; fixed[key] = $3 "|" $4 ".." $5; keys[key] = 1 }
        END {
            printf "%-30s %-46s %-22s %s\n", "goal", "figure (median)", "target", "verdict"
            lost = "-"; fps = "-"; ratio = "-"; idle = "-"
            for (key in keys) {
                split(key, k, SUBSEP); v = med(key) + 0
                # Goal 1 holds the cases whose read load is at most half of the capacity of the link.
                if (k[1] == "poll_record_bench" && k[2] ~ / lost$/) {
                    split(k[2], c, " "); load = c[4] * 1000 / c[2]; cap = med("poll_record_bench" SUBSEP c[1] " capacity") + 0
                    if (cap > 0 && load <= cap / 2 && (lost == "-" || v > lost)) lost = v
                    if (cap > 0 && load > cap / 2) over = over " " c[1] " " c[2] " ms x " c[4] }
                if (k[1] == "scope_plot_bench" && k[2] ~ /full/ && k[2] !~ /CPU/ && (fps == "-" || v < fps)) fps = v
                if (k[1] == "engine_vs_minimal" && k[2] ~ /engine\/minimal$/ && (ratio == "-" || v < ratio)) ratio = v
                if (k[1] == "gui_idle_bench" && k[2] ~ /GUI without/) idle = v
            }
            goal("1 polling: samples lost", lost == "-" ? "-" : "worst case at <= half capacity: " lost " %", "0 %", lost == 0)
            if (over != "") printf "%-30s %s\n", "", "(above half the capacity measured, not judged:" over ")"
            goal("2 scope: full view", fps == "-" ? "-" : "slowest case: " fps " fps", ">= 120 fps", fps >= 120)
            goal("3 engine: rate of minimal", ratio == "-" ? "-" : "lower of RefGo, SDO: " ratio, ">= 0.90", ratio >= 0.90)
            goal("4 idle GUI with the demo", idle == "-" ? "-" : "GUI without the demo devices: " idle " %", "< 3 % of a core", idle < 3)
        }' "$figures"
} | tee "$out/table.txt"
echo "full outputs in $out/"

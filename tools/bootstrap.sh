#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (run as root, or as a user with sudo):
#   bash tools/bootstrap.sh demo   install dependencies, build, start `drivebench --demo`
#   bash tools/bootstrap.sh test   install dependencies, build, run the whole test suite (ctest),
#                                  then build it once more with the sanitizers and run it there
#                                  (tools/sanitize.sh; DRIVEBENCH_SANITIZER_PASS=OFF skips that)
#   bash tools/bootstrap.sh build  install dependencies and build only
#   bash tools/bootstrap.sh deb    install dependencies, build, make build/drivebench_*.deb
#                                  (cpack) and check it with lintian
# Environment: BUILD_DIR (default: build), CI=true turns warnings into errors,
# DRIVEBENCH_CMAKE_ARGS: more options for cmake. `test` builds from scratch with precompiled Qt
# headers, without debug information and with mold unless DRIVEBENCH_CMAKE_ARGS is set (also
# when set to nothing): about half the CPU time of a plain build without a compiler cache.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in
demo | test | build | deb) ;;
*)
    echo "usage: bash tools/bootstrap.sh demo|test|build|deb" >&2
    exit 2
    ;;
esac

# Everything the build, the tests and the demo need, from Debian 12's own archive.
# Camera (Morse panel): Qt 6.4 on Debian uses its GStreamer media backend; V4L2 cameras are
# listed and opened by GStreamer's v4l2 plugin from gstreamer1.0-plugins-good.
packages=(
    cmake ninja-build g++ pkg-config
    qt6-base-dev qt6-serialbus-dev libqt6serialbus6
    qt6-l10n-tools qt6-translations-l10n                # lupdate/lrelease; Qt's German texts
    libqcustomplot-dev libeigen3-dev
    libavformat-dev libavcodec-dev libswscale-dev libavutil-dev
    qt6-multimedia-dev gstreamer1.0-plugins-good
    fonts-dejavu-core xvfb xauth
    python3 librsvg2-bin                                 # man pages from --help, PNG icons
    desktop-file-utils appstream bash-completion         # tst_packaging's validators
    python3-can                                          # a third-party CANopen master in tests
    clang-format                                         # tst_format
    mold                                                 # a fast linker (DRIVEBENCH_LINKER)
)
# The .deb: dpkg-shlibdeps (dpkg-dev) and file for its dependencies, lintian to check it.
if [ "$mode" = deb ]; then
    packages+=(dpkg-dev file lintian)
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    echo "installing: ${missing[*]}"
    $sudo apt-get update -q
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q "${missing[@]}"
fi

build_dir=${BUILD_DIR:-build}
if [ "$mode" = test ] && [ -z "${DRIVEBENCH_CMAKE_ARGS+set}" ]; then
    DRIVEBENCH_CMAKE_ARGS="-DDRIVEBENCH_PCH=ON -DDRIVEBENCH_DEBUG_INFO=OFF -DDRIVEBENCH_LINKER=mold"
fi
export DRIVEBENCH_CMAKE_ARGS=${DRIVEBENCH_CMAKE_ARGS:-} # tools/sanitize.sh takes them too
werror=OFF
[ "${CI:-}" = "true" ] || [ "${DRIVEBENCH_WERROR:-}" = "ON" ] && werror=ON
# shellcheck disable=SC2086 # DRIVEBENCH_CMAKE_ARGS is a list of options
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDRIVEBENCH_WERROR="$werror" \
    ${DRIVEBENCH_CMAKE_ARGS:-}
cmake --build "$build_dir" --parallel "$(nproc)"

case "$mode" in
demo)
    if [ -z "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
        echo "no display found: starting the demo under xvfb-run (invisible)" >&2
        exec xvfb-run -a "$build_dir/app/drivebench" --demo
    fi
    exec "$build_dir/app/drivebench" --demo
    ;;
test)
    # Three tests at a time on two cores: the normal build's tests wait for timers and sockets
    # most of the time (with three: 1.4 cores busy, the suite 226 s; with two: 346 s). The
    # processor time they leave goes to the sanitizer build, which starts with them at the lowest
    # priority (nice 19: a test that wants the processor gets it). The sanitizer pass keeps one
    # test per core: its instrumented tests keep the processor busy.
    sanitizer_pass=${DRIVEBENCH_SANITIZER_PASS:-ON}
    sanitize_log=$build_dir/sanitize-build.log
    san_pid=
    if [ "$sanitizer_pass" != OFF ]; then
        # Its own process group (set -m), in this session, so that nice counts against the
        # tests and a failing suite ends the build with it.
        set -m
        nice -n 19 bash tools/sanitize.sh build >"$sanitize_log" 2>&1 &
        san_pid=$!
        set +m
        trap '[ -n "$san_pid" ] && kill -- "-$san_pid" 2>/dev/null; true' EXIT
    fi
    (cd "$build_dir" && QT_QPA_PLATFORM=offscreen ctest --output-on-failure \
        --parallel "$(($(nproc) * 3 / 2))" --timeout 300)
    if [ "$sanitizer_pass" != OFF ]; then
        echo "the sanitizer build (begun beside the suite above):" >&2
        san_rc=0
        wait "$san_pid" || san_rc=$?
        san_pid=
        cat "$sanitize_log"
        [ "$san_rc" = 0 ] || exit "$san_rc"
        echo "the whole suite once more under AddressSanitizer, UBSan and LeakSanitizer" >&2
        bash tools/sanitize.sh
    fi
    ;;
deb)
    rm -f "$build_dir"/drivebench_*.deb
    (cd "$build_dir" && cpack -G DEB)
    deb=$(ls "$build_dir"/drivebench_*.deb)
    lintian --fail-on error "$deb"
    case "$deb" in /*) ;; *) deb=./$deb ;; esac # apt takes a path, not a package name
    echo "built $deb; install it with: apt install $deb"
    ;;
build) ;;
esac

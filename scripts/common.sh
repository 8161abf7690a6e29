# Shared by the scripts (run, test, fuzz, sanitize): Debian packages and the builds.
# Sourced, not run.

SYLVA_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SYLVA_BUILD="${SYLVA_BUILD:-$SYLVA_ROOT/build}"

# What building Sylva needs (see third_party_notes.md for why each one).
SYLVA_BUILD_PACKAGES=(cmake g++ make pkg-config libglm-dev libtbb-dev nlohmann-json3-dev
    libopenvdb-dev libboost-iostreams-dev libtomlplusplus-dev libtinygltf-dev
    libgtest-dev libglfw3-dev libimgui-dev libstb-dev libgl-dev libmeshoptimizer-dev libcgal-dev
    libpng-dev)

as_root() {
    if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# Installs the packages that are missing; does nothing (and needs no network) otherwise.
ensure_packages() {
    local missing=()
    for p in "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
            missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "sylva: installing ${missing[*]}"
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        "${missing[@]}" >/dev/null
}

# Extra arguments go to CMake's configure step (e.g. -DSYLVA_WERROR=ON).
build_sylva() {
    cmake -S "$SYLVA_ROOT" -B "$SYLVA_BUILD" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
    cmake --build "$SYLVA_BUILD" --parallel "$(nproc)"
}

# Fails, listing the files, when a C++ file of the tree differs from what clang-format
# (the committed .clang-format) makes of it. Fix with: scripts/format
check_format() {
    local files
    mapfile -t files < <(git -C "$SYLVA_ROOT" ls-files '*.cpp' '*.h')
    if ! (cd "$SYLVA_ROOT" && clang-format --dry-run -Werror "${files[@]}" 2>/tmp/sylva-format.$$); then
        grep -o '^[^:]*:[0-9]*:[0-9]*: error' /tmp/sylva-format.$$ | cut -d: -f1 | sort -u |
            sed 's/^/sylva: not formatted: /'
        rm -f /tmp/sylva-format.$$
        echo "sylva: run scripts/format and commit the result"
        return 1
    fi
    rm -f /tmp/sylva-format.$$
}

# The sanitizer build (scripts/fuzz, scripts/sanitize): clang with ASan + UBSan, libFuzzer's
# coverage on every library, asserts on, the unit tests and the fuzzers, no GUI. Warnings
# are not errors here: the GCC build of scripts/test is the one held to -Werror.
SYLVA_SANITIZED_BUILD="${SYLVA_SANITIZED_BUILD:-$SYLVA_ROOT/build-fuzz}"
SYLVA_SANITIZER_PACKAGES=(clang libclang-rt-14-dev)

# What the sanitized unit tests and fuzzers run with: stop at the first report, leaks
# included. intercept_tls_get_addr=0: up to LLVM 16 the __tls_get_addr interceptor takes
# some dynamic TLS blocks for glibc 2.19's (when tls_beg % 4096 happens to equal that
# header's size) and hands LeakSanitizer a bogus range, and its tracer segfaults at exit
# after a passing test ("Tracer caught signal 11", google/sanitizers#1322): seen in CI on a
# test that runs OpenVDB's mesher under TBB, 11 of 80 runs under load, 0 of 80 with it.
export_sanitizer_options() {
    export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:intercept_tls_get_addr=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
    export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
}

# Configures DIR for clang (asserts on, -O1, line tables for the sanitizers' reports, no
# benches) with the -D options given before "--", then builds the targets after it (all
# when none).
build_with_clang() {
    local dir="$1" options=() targets=()
    shift
    while [ $# -gt 0 ] && [ "$1" != "--" ]; do
        options+=("$1")
        shift
    done
    [ $# -gt 0 ] && shift
    for t in "$@"; do targets+=(--target "$t"); done
    cmake -S "$SYLVA_ROOT" -B "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
        -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" -DSYLVA_BUILD_BENCH=OFF \
        -DSYLVA_BUILD_TESTS=ON -DSYLVA_WERROR=OFF "${options[@]}" >/dev/null
    cmake --build "$dir" --parallel "$(nproc)" "${targets[@]}"
}

# Arguments: the targets to build (all when none).
build_sylva_sanitized() {
    build_with_clang "$SYLVA_SANITIZED_BUILD" -DSYLVA_SANITIZE=ON -DSYLVA_BUILD_FUZZERS=ON \
        -DSYLVA_BUILD_UI=OFF -- "$@"
}

# The ThreadSanitizer build (scripts/sanitize): clang with TSan, asserts on, the studio's
# state library and the unit tests, no fuzzers or benches.
SYLVA_TSAN_BUILD="${SYLVA_TSAN_BUILD:-$SYLVA_ROOT/build-tsan}"

# Arguments: the targets to build (all when none). Unoptimized: its few tests run in
# seconds either way, and -O0 builds it faster.
build_sylva_tsan() {
    build_with_clang "$SYLVA_TSAN_BUILD" -DSYLVA_TSAN=ON \
        -DCMAKE_CXX_FLAGS_DEBUG="-O0 -gline-tables-only" -- "$@"
}

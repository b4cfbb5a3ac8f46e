#!/usr/bin/env bash
# Installs what building and testing tilesweep needs, from Debian's packages, when missing.
# Run by the scripts a person starts (main.sh, test.sh, audit.sh, conformance.sh, ...), never by
# scripts/build.sh, which only says what is missing; safe to run again (it installs nothing
# twice). Sourced, it only defines its functions (tilesweep_setup_base installs the base set). Every apt-get runs under one machine-wide lock, so that setups started
# together install one after the other, and after `dpkg --configure -a` when dpkg was interrupted.
#
#   bash scripts/setup.sh                        # the packages every build needs
#   bash scripts/setup.sh --engines              # those, and every engine adapter's runtime
#   bash scripts/setup.sh --engines godot        # those, and one engine's (adapters/ENGINE/install.sh)
#   bash scripts/setup.sh --packages PKG...      # only the Debian packages PKG... (the adapters' installs)
#
# Scripts that need more (scripts/fuzz.sh: clang) name it in TILESWEEP_EXTRA_PACKAGES.
set -euo pipefail

TILESWEEP_PACKAGES=(
    g++ cmake ninja-build
    libgtest-dev librapidcheck-dev       # unit tests and the property suite
    libboost-dev libgmp-dev              # the exact rational oracle (Boost.Multiprecision, GMP)
    nlohmann-json3-dev libcli11-dev      # scene files, the command line
    libbenchmark-dev libbox2d-dev        # benchmarks, and Box2D as the peer they measure against
    luajit                               # examples/love_style: the C API from LuaJIT's FFI
)

tilesweep_missing_packages() {  # PKG...: prints those not installed, one a line
    local package
    for package in "$@"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || echo "$package"
    done
}

tilesweep_lock_file() {  # NAME: prints a lock file NAME that every user here can open
    local file
    for file in "/var/lock/$1" "${TMPDIR:-/tmp}/$1"; do
        [ -r "$file" ] || (umask 0 && : >>"$file") 2>/dev/null || true
        if [ -r "$file" ]; then
            echo "$file"
            return 0
        fi
    done
    echo "setup: cannot create the lock file $1 in /var/lock or ${TMPDIR:-/tmp}" >&2
    return 1
}

tilesweep_dpkg_interrupted() {  # true when dpkg reports a half-done install, or left its journal
    [ -n "$(dpkg --audit 2>/dev/null)" ] || compgen -G '/var/lib/dpkg/updates/[0-9]*' >/dev/null
}

tilesweep_apt_install() {  # PKG...: installs those of the Debian packages PKG... that are missing
    local missing lock
    mapfile -t missing < <(tilesweep_missing_packages "$@")
    ((${#missing[@]})) || return 0
    lock=$(tilesweep_lock_file tilesweep-setup.lock) || return 1
    # A subshell holds the lock (fd 9), so that none stays open in a shell that sources this file.
    (
        if ! flock -n 9; then
            echo "setup: waiting for another setup to finish (lock $lock)" >&2
            flock -w 1800 9 || { echo "setup: $lock is still held after 30 minutes" >&2; exit 1; }
        fi
        # The setup that held the lock may have installed them.
        mapfile -t missing < <(tilesweep_missing_packages "${missing[@]}")
        ((${#missing[@]})) || exit 0
        echo "setup: installing ${missing[*]}" >&2
        sudo_cmd=()
        if [ "$(id -u)" -ne 0 ]; then
            if ! command -v sudo >/dev/null; then
                echo "setup: could not install ${missing[*]} (not root, and no sudo): run as root: apt-get install ${missing[*]}" >&2
                exit 1
            fi
            sudo_cmd=(sudo)
        fi
        log=$(mktemp)
        trap 'rm -f "$log"' EXIT
        if tilesweep_dpkg_interrupted; then
            echo "setup: dpkg was interrupted: running dpkg --configure -a first" >&2
            if ! "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive dpkg --configure -a >"$log" 2>&1; then
                tail -n 20 "$log" >&2
                echo "setup: dpkg --configure -a failed: run it as root, then: apt-get install ${missing[*]}" >&2
                exit 1
            fi
        fi
        # A failed update leaves the lists apt has; the install says whether they are enough.
        "${sudo_cmd[@]}" apt-get update -qq >>"$log" 2>&1 || true
        if ! "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
            -o DPkg::Lock::Timeout=600 "${missing[@]}" >>"$log" 2>&1; then
            tail -n 20 "$log" >&2
            echo "setup: could not install ${missing[*]}: run as root: apt-get install ${missing[*]}" >&2
            exit 1
        fi
    ) 9<"$lock"
}

tilesweep_setup_base() {  # the packages every build needs, and TILESWEEP_EXTRA_PACKAGES
    local extra
    read -r -a extra <<<"${TILESWEEP_EXTRA_PACKAGES:-}"
    tilesweep_apt_install "${TILESWEEP_PACKAGES[@]}" "${extra[@]}"
}

tilesweep_setup_engines() {  # [ENGINE...]: each engine adapter's runtime (default: every one)
    local adapters engines engine failed=()
    adapters="$(cd "$(dirname "${BASH_SOURCE[0]}")/../adapters" && pwd)"
    engines=("$@")
    if ((${#engines[@]} == 0)); then
        for engine in "$adapters"/*/install.sh; do
            engines+=("$(basename "$(dirname "$engine")")")
        done
    fi
    for engine in "${engines[@]}"; do
        if [ ! -f "$adapters/$engine/install.sh" ]; then
            echo "setup: no engine '$engine' (adapters/*/install.sh: $(cd "$adapters" && echo */install.sh | sed 's|/install.sh||g'))" >&2
            return 2
        fi
    done
    for engine in "${engines[@]}"; do
        bash "$adapters/$engine/install.sh" || failed+=("$engine")
    done
    if ((${#failed[@]})); then
        echo "setup: the runtime of ${failed[*]} is not installed (see above)" >&2
        return 1
    fi
}

tilesweep_require_base() {  # says what tilesweep_setup_base would install, and fails, when anything
    local extra missing
    read -r -a extra <<<"${TILESWEEP_EXTRA_PACKAGES:-}"
    mapfile -t missing < <(tilesweep_missing_packages "${TILESWEEP_PACKAGES[@]}" "${extra[@]}")
    ((${#missing[@]})) || return 0
    echo "build: missing Debian packages: ${missing[*]}: run  bash scripts/setup.sh  (or scripts/test.sh or" \
        "scripts/main.sh, which install them), or as root: apt-get install ${missing[*]}" >&2
    return 1
}
if [ "${BASH_SOURCE[0]}" = "$0" ]; then
    case "${1:-}" in
        "") tilesweep_setup_base ;;
        --engines) shift; tilesweep_setup_base; tilesweep_setup_engines "$@" ;;
        --packages) shift; tilesweep_apt_install "$@" ;;
        -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}" ;;
        *) echo "setup.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    esac
fi

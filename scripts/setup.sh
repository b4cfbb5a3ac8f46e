#!/usr/bin/env bash
# Installs what building and testing tilesweep needs, from Debian's packages, when missing.
# Sourced by scripts/main.sh and scripts/test.sh; safe to run again (it installs nothing twice).
set -euo pipefail

TILESWEEP_PACKAGES=(
    g++ cmake ninja-build
    libgtest-dev librapidcheck-dev       # unit tests and the property suite
    libboost-dev libgmp-dev              # the exact rational oracle (Boost.Multiprecision, GMP)
    nlohmann-json3-dev libcli11-dev      # scene files, the command line
    libbenchmark-dev libbox2d-dev        # benchmarks, and Box2D as the peer they measure against
    luajit                               # examples/love_style: the C API from LuaJIT's FFI
)

# Scripts that need more (scripts/fuzz.sh: clang) name it in TILESWEEP_EXTRA_PACKAGES.
read -r -a extra <<<"${TILESWEEP_EXTRA_PACKAGES:-}"
TILESWEEP_PACKAGES+=("${extra[@]}")

missing=()
for package in "${TILESWEEP_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
    echo "setup: installing ${missing[*]}" >&2
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

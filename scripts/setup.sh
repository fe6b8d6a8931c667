#!/usr/bin/env bash
# Shared set-up for the README's two commands: installs the Debian 12 packages that are missing,
# then configures and builds ffrf (Release) in ./build. Idempotent; quiet when nothing is missing.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config libeigen3-dev libarpack2-dev liblapack-dev libspectra-dev libsundials-dev
          libsuitesparse-dev libtomlplusplus-dev libcli11-dev libfmt-dev nlohmann-json3-dev libgtest-dev
          libbenchmark-dev gnuplot-nox libfftw3-dev libnetcdf-dev libopenmpi-dev openmpi-bin
          pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "ffrf set-up: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
# ccache, when the machine has it, makes rebuilds of unchanged files free (not needed, not installed).
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFFRF_WERROR="$werror" "${launcher[@]}" > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j"$(nproc)" >> build.log 2>&1 || { tail -n 60 build.log; echo "build failed: full log in build.log"; exit 1; }
echo "ffrf set-up: built in ./build (log: build.log)"

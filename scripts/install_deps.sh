#!/usr/bin/env bash
# Installs grit's build and test dependencies from Debian's packages.
# Idempotent: does nothing (and needs no network) when everything is already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev libfmt-dev libspdlog-dev
  libgtest-dev libgmock-dev libbenchmark-dev libomp-dev
  libhdf5-dev hdf5-tools
  python3 python3-numpy python3-matplotlib python3-vtk9
  python3-dev pybind11-dev python3-pytest  # the Python module (docs/python.md) and its tests
  liggghts-doc  # the STL chute of LIGGGHTS' chute_wear tutorial (cases/chute_wear_3d); 12 MB, no binaries
  clang-14 libclang-rt-14-dev llvm-14  # make fuzz: libFuzzer, clang's sanitizers and llvm-cov (fuzz/)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

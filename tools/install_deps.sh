#!/usr/bin/env bash
# Installs the Debian packages flapsim is built on, but only those missing.
# Called by `make build`/`make test`/`make run`; safe to run again (does nothing
# when everything is present). Uses sudo when not root.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  ccache  # used by CMakeLists.txt when present: a rebuild of unchanged sources is free
  libeigen3-dev libspectra-dev
  libgmsh-dev gmsh
  libvtk9-dev
  libsuitesparse-dev
  libblas3 liblapack3  # the reference BLAS/LAPACK under CHOLMOD (docs/fem.md, "The dense kernels under the factorisation")
  libgtest-dev libgmock-dev libbenchmark-dev
  libtomlplusplus-dev libcli11-dev
  libsimbody-dev
  libopenmpi-dev openmpi-bin
  libnlopt-cxx-dev  # flapsim optimize (NLopt: BOBYQA, COBYLA)
  python3-matplotlib
  python3-vtk9 xvfb xauth
  ffmpeg  # make movie: tools/paraview_state.py --movie encodes the frames (H.264 MP4)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "flapsim: installing missing Debian packages: ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "flapsim: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"

#!/usr/bin/env bash
# Installs the Debian 12 packages gearkit builds and tests with, if any is missing.
# Idempotent: when everything is present it runs no apt command at all; otherwise it runs
# `apt-get update` once and installs only what is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev
  libsuitesparse-dev
  libboost-dev libboost-program-options-dev libboost-filesystem-dev
  libyaml-cpp-dev libyaml-dev nlohmann-json3-dev libfmt-dev
  libcgal-dev libgmp-dev libmpfr-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-ezdxf python3-yaml
  universal-ctags
  libslvs1-dev
  libmuparser-dev
  libnlopt-dev
  libginac-dev
  chromium librecad poppler-utils   # ctest render.html_and_pdf: HTML pages in a browser, DXF to PDF
)
# The Python module (python/, docs/python.md; CMake option GEARKIT_PYTHON): pybind11 to build it,
# NumPy for its arrays, pandas for Sweep.to_dataframe(), for Debian's /usr/bin/python3.
python_packages=(pybind11-dev python3-dev python3-numpy python3-pandas)
packages+=("${python_packages[@]}")

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup-deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"

#!/usr/bin/env bash
# Installs the Debian 12 packages gearkit needs, if any is missing.
#   setup-deps.sh           what the executable and its plugins need to build and run (`make demo`,
#                           `make build`, `make install`)
#   setup-deps.sh --test    and what the test suite needs besides (`make test`): GoogleTest, Python
#                           with ezdxf and PyYAML, ctags, and the HTML/PDF renderers of the render test
#   setup-deps.sh --bench   and what the benchmarks need besides (`make bench`)
# The groups are kept apart so that a fresh machine's first result (`make demo`) waits for no
# browser, CAD program or test framework (issue 26, section 4).
# Idempotent: when everything is present it runs no apt command at all; otherwise it runs
# `apt-get update` once and installs only what is missing.
set -euo pipefail

build_packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev
  libsuitesparse-dev
  libboost-dev libboost-program-options-dev
  libyaml-cpp-dev libyaml-dev nlohmann-json3-dev libfmt-dev
  libcgal-dev libgmp-dev libmpfr-dev
  libmuparser-dev
  libnlopt-dev
  libginac-dev
)
test_packages=(
  libgtest-dev libgmock-dev
  python3 python3-ezdxf python3-yaml
  universal-ctags
  chromium librecad poppler-utils   # ctest render.html_and_pdf: HTML pages in a browser, DXF to PDF
)
bench_packages=(
  libbenchmark-dev
  libslvs1-dev                      # SolveSpace's solver, the peer of bench_kin
)
# The Python module (python/, docs/python.md; CMake option GEARKIT_PYTHON, off by default): pybind11
# to build it, NumPy for its arrays, pandas for Sweep.to_dataframe(), for Debian's /usr/bin/python3.
python_packages=(pybind11-dev python3-dev python3-numpy python3-pandas)

packages=("${build_packages[@]}")
for arg in "$@"; do
  case "$arg" in
    --test) packages+=("${test_packages[@]}") ;;
    --bench) packages+=("${bench_packages[@]}") ;;
    --python) packages+=("${python_packages[@]}") ;;
    *) echo "setup-deps: unknown argument '$arg' (expected --test, --bench or --python)" >&2; exit 2 ;;
  esac
done

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

#!/usr/bin/env bash
# Installs the built gearkit into a scratch prefix, builds examples/plugin-hello against it with
# find_package(gearkit), and runs the installed gearkit with the plugin on GEARKIT_PLUGIN_PATH.
# Usage: out_of_tree_plugin.sh BUILD_DIR PLUGIN_SOURCE_DIR SCRATCH_DIR
set -euo pipefail
build=$1 src=$2 scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch"
prefix=$scratch/prefix
cmake --install "$build" --prefix "$prefix" > "$scratch/install.log"

# The installed tree has what the issue asks for.
for f in bin/gearkit lib/gearkit/plugins/gearkit-gear.so lib/gearkit/plugins/gearkit-train.so \
         lib/gearkit/plugins/gearkit-cam.so lib/cmake/gearkit/gearkitConfig.cmake \
         include/gearkit/plugin/plugin.hpp include/gearkit/mechanism/element_type.hpp include/gearkit/io/report.hpp; do
  [ -e "$prefix/$f" ] || { echo "missing in install: $f"; exit 1; }
done

cmake -S "$src" -B "$scratch/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_EXPORT_COMPILE_COMMANDS=ON > "$scratch/configure.log"
cmake --build "$scratch/build" > "$scratch/build.log"
plugin=$(find "$scratch/build" -name 'gearkit-hello.so' | head -n 1)
[ -n "$plugin" ] || { echo "plugin was not built"; exit 1; }
# A plugin of commands only needs neither the solver nor Eigen (issue 12): not linked, not even
# on its include path.
if readelf -d "$plugin" | grep -q 'NEEDED.*libgearkit_kin'; then echo "plugin-hello links libgearkit_kin"; exit 1; fi
if grep -q -i 'eigen3' "$scratch/build/compile_commands.json"; then echo "plugin-hello compiles with Eigen"; exit 1; fi

out=$(GEARKIT_PLUGIN_PATH="$(dirname "$plugin")" "$prefix/bin/gearkit" hello --name Ada)
[ "$out" = "hello, Ada

Warnings: none" ] || { echo "unexpected output: $out"; exit 1; }
json=$(GEARKIT_PLUGIN_PATH="$(dirname "$plugin")" "$prefix/bin/gearkit" hello --format json)
echo "$json" | grep -q '"greeting": "hello, world"' || { echo "unexpected json: $json"; exit 1; }
# The installed gearkit finds its own plugins in lib/gearkit/plugins.
listing=$(GEARKIT_PLUGIN_PATH="$(dirname "$plugin")" "$prefix/bin/gearkit" plugins)
for p in gear train cam hello; do
  echo "$listing" | grep -q "^  $p " || { echo "plugin $p not listed: $listing"; exit 1; }
done
echo "out-of-tree plugin: OK"

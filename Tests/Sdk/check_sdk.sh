#!/bin/sh
# The SDK as a user meets it: install the build into a fresh prefix, build
# the template plugin (Demos/plugin-template) against it out of the tree,
# run its unit tests, run its scene and an installed scene with the
# installed soak from another directory, and check that a plugin built
# against another Soak version is refused (exit 2, a clear message).
#   check_sdk.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -eu
build=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work/elsewhere"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
for f in bin/soak bin/soak-bench lib/libsoak_core.so lib/soak-plugins/libsoak_WetCloth.so \
         lib/cmake/Soak/SoakConfig.cmake lib/cmake/Soak/SoakConfigVersion.cmake \
         include/soak/Simulation/Simulation.h include/soak/Support/TestScenes.h share/soak/Scenes/fig7_small.xml; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
configure() {  # configure DIR [extra cmake args]
  dir=$1; shift
  cmake -S "$src/Demos/plugin-template" -B "$dir" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" "$@" > "$dir.log" 2>&1 ||
    { cat "$dir.log"; exit 1; }
  cmake --build "$dir" >> "$dir.log" 2>&1 || { cat "$dir.log"; exit 1; }
}
configure "$work/template"
ctest --test-dir "$work/template" --output-on-failure
cd "$work/elsewhere"
plugin=$work/template/soak-plugins/libsoak_SteadyWind.so
"$prefix/bin/soak" run "$prefix/share/soak/plugin-template/Scenes/wind_drop.xml" --plugin "$plugin" -o wind \
  --device cpu --quiet --profile > profile.txt
grep -q "wind.relax" profile.txt || { echo "the plugin's stage did not run"; cat profile.txt; exit 1; }
[ -f wind/water.pvd ] || { echo "no output"; exit 1; }
"$prefix/bin/soak" run "$prefix/share/soak/Scenes/fig7_small.xml" -o fig7 --frames 2 --device cpu --quiet
[ -f fig7/cloth_sheet.pvd ] || { echo "fig7: no output"; exit 1; }
# The same plugin, as if built against another Soak.
configure "$work/template-other" "-DCMAKE_CXX_FLAGS=-DSOAK_PLUGIN_BUILT_FOR=\\\"0.0.0-other\\\""
set +e
"$prefix/bin/soak" run "$prefix/share/soak/plugin-template/Scenes/wind_drop.xml" \
  --plugin "$work/template-other/soak-plugins/libsoak_SteadyWind.so" -o refused --device cpu --quiet 2> refused.txt
rc=$?
set -e
[ "$rc" = 2 ] || { echo "a plugin built for another version: exit $rc, expected 2"; cat refused.txt; exit 1; }
grep -q "built against Soak 0.0.0-other" refused.txt || { echo "unclear refusal:"; cat refused.txt; exit 1; }
[ ! -e refused ] || { echo "a refused run wrote output"; exit 1; }
echo "SDK: installed, template plugin built and tested out of tree, scenes run, version mismatch refused:"
cat refused.txt

#!/usr/bin/env bash
# Builds a plugin jar of the knowledge core from a plugin folder, against the installed core
# (source install/setup.bash first). Any plugin laid out as examples/plugins/hello_command is:
#   PLUGIN_DIR/src/**.java       its classes
#   PLUGIN_DIR/META-INF/...      its services files (io.github.armor.core.spi.CommandGroup)
#   PLUGIN_DIR/lib/*.jar         libraries it needs (optional): compiled against, copied beside it
# Usage:
#   bash examples/plugins/build.sh PLUGIN_DIR OUT_DIR [JAR_NAME]   (default: PLUGIN_DIR's name.jar)
# then start a node with it (the installed plugins stay loaded):
#   armor serve --ros-args -p plugin_dirs:=OUT_DIR
# A running node reads its plugin jars at start only: restart it to load a new or rebuilt jar.
set -euo pipefail
usage="usage: build.sh PLUGIN_DIR OUT_DIR [JAR_NAME]"
plugin="$(cd "${1:?$usage}" && pwd)"
out="$(mkdir -p "${2:?$usage}" && cd "$2" && pwd)"
jar_name="${3:-$(basename "$plugin").jar}"
core="${ARMOR_CORE_JAR:?source install/setup.bash first}"
[ -d "$plugin/src" ] || { echo "build.sh: $plugin has no src folder of .java files" >&2; exit 2; }
classes="$(mktemp -d)"
trap 'rm -rf "$classes"' EXIT
classpath="$core:$(dirname "$core")/lib/*"
if [ -d "$plugin/lib" ]; then
  classpath="$classpath:$plugin/lib/*"
fi
find "$plugin/src" -name '*.java' -print0 | xargs -0 javac -d "$classes" -cp "$classpath"
if [ -d "$plugin/META-INF" ]; then
  cp -r "$plugin/META-INF" "$classes/"
fi
jar --create --file "$out/$jar_name" -C "$classes" .
if [ -d "$plugin/lib" ]; then
  cp "$plugin"/lib/*.jar "$out/"
fi
echo "built $out/$jar_name"

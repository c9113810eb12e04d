#!/usr/bin/env bash
# Builds hello.jar from this folder against the installed core (source install/setup.bash first):
#   bash examples/plugins/hello_command/build.sh OUT_DIR
# then start a node with it:  armor serve --ros-args -p plugin_dirs:=OUT_DIR
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="$(mkdir -p "${1:?usage: build.sh OUT_DIR}" && cd "$1" && pwd)"
classes="$(mktemp -d)"
trap 'rm -rf "$classes"' EXIT
core="${ARMOR_CORE_JAR:?source install/setup.bash first}"
javac -d "$classes" -cp "$core:$(dirname "$core")/lib/*" "$here"/src/example/*.java
cp -r "$here/META-INF" "$classes/"
jar --create --file "$out/hello.jar" -C "$classes" .
echo "built $out/hello.jar"

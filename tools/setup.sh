#!/usr/bin/env bash
# Set up ARMOR for ROS 2, idempotently, with independent steps side by side.
#
#   bash tools/setup.sh [PART...]      (from anywhere; --list shows the steps)
#
# Without PART it installs what running needs (`armor serve`, `armor call`, the web view):
# make setup and make run. Each PART adds one step, or all steps of a group:
#   test       every step `make test` needs (linters, planner, browser, cpp, colcon)
#   cpp        the C++ client (make cpp); with `test` also its GoogleTest tests
#   planner    pyperplan, for the PDDL bridge's plans (make demo-plan)
#   ... or any step's name (tools/setup.sh --list).
#
# A step is one function step_<name> and one `step` line in the table below (its group and
# the steps it needs). A step starts as soon as the steps it needs are done: on a fresh
# machine the Java core downloads and compiles while the ROS 2 wheels install and armor_msgs
# is generated. A step is skipped when the sha256 of its inputs matches its stamp in
# build/stamps/ and its output is still there. Each says what it does and how long it took;
# its log is build/logs/<step>.log. Steps that install into .venv with uv take turns
# (venv_install), and so do those that call apt-get (apt_install).
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
# Where PYTHONDONTWRITEBYTECODE is set (CI machines often set it) no import writes a .pyc, and
# every Python process of the set-up (dozens of message generators) compiled what it imported
# again. The set-up writes only into build/, install/ and .venv, so it lets imports cache.
unset PYTHONDONTWRITEBYTECODE

die() { echo "setup.sh: ERROR: $*" >&2; exit 1; }

# ---------------------------------------------------------------- the steps
# step NAME GROUP NEEDS WHAT: GROUP is run (always), test (with PART test) or opt (only when
# named, or when a selected step needs it). NEEDS: steps that must be done first.
declare -A STEP_GROUP STEP_NEEDS STEP_WHAT
STEP_NAMES=()
step() { STEP_NAMES+=("$1"); STEP_GROUP[$1]=$2; STEP_NEEDS[$1]=$3; STEP_WHAT[$1]=$4; }
#    name       group  needs            what
step venv       run    ""               "pinned ROS 2 wheels (tools/requirements-ros2.txt) in .venv"
step maven      run    ""               "a pinned Maven 3.9 (SHA-512 checked) from Maven Central, for the Java steps"
step core       run    "maven"          "the Java core, built with Maven (its libraries downloaded once)"
step archive    run    "core"           "the core's class data archive (AppCDS): a core start maps its classes instead of loading them"
step env        run    ""               "install/setup.bash and install/setup.sh"
step armor_msgs run    "venv"           "armor_msgs generated and compiled into install/armor_msgs (C++ too for cpp)"
step web        run    "venv"           "the web view: aiohttp, and cytoscape.js from the npm registry"
step python     run    "venv"           "armor_contract, armor_service, armor_client installed editable"
step scenes     run    "venv"           "the scene service: sit_armor_injected_msgs and its node extension"
step plugins    run    "core"           "the core's plugins (plugins/*/pom.xml) into install/armor_plugins"
step lint       test   "venv"           "flake8, pydocstyle, mypy (tools/requirements-lint.txt)"
step planner    test   "venv"           "pyperplan (tools/requirements-planning.txt), for PDDL plans"
step browser    test   "venv"           "Playwright and Debian's chromium, for the web view's tests"
step cpp        test   "armor_msgs"     "the C++ client armor_cpp into install/armor_cpp"
step testrunner test   "venv"           "pytest-xdist (tools/requirements-test-runner.txt), test files side by side"
step colcon     test   "venv"           "colcon (tools/requirements-colcon.txt), for the colcon workspace test"
step faketime   test   ""               "Debian's libfaketime, for the clock-jump test (test_clock_jumps.py)"

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
# up_to_date HASH [TEST...]: true when the stamp of this step holds HASH and TEST succeeds;
# says so. Otherwise the stamp is removed (a step stopped half way is redone next time).
up_to_date() {
  local hash="$1"; shift
  if [ -f "$STAMPS/$STEP" ] && [ "$(cat "$STAMPS/$STEP")" = "$hash" ] && { [ $# = 0 ] || "$@"; }; then
    echo "$STEP: up to date"
    return 0
  fi
  rm -f "$STAMPS/$STEP"
  return 1
}
# begin TEXT: say what the step does; its log starts empty. done_in HASH TEXT: stamp and say.
begin() {
  STEP_T0=$EPOCHREALTIME; cpu_ticks; STEP_TICKS0=$CPU_TICKS
  : > "$LOGS/$STEP.log"; echo "$STEP: $* (log: build/logs/$STEP.log)"
}
done_in() {
  printf '%s\n' "$1" > "$STAMPS/$STEP"
  cpu_ticks
  echo "$STEP: $2 in $(seconds_since "$STEP_T0") s ($(awk -v t=$((CPU_TICKS - STEP_TICKS0)) \
    -v hz="$CLOCK_TICKS" 'BEGIN { printf "%.1f", t / hz }') CPU-s)"
}
# cpu_ticks: CPU_TICKS = CPU time of this step's shell and the children it waited for (no fork:
# a subshell would count only itself). Two cores share the set-up, so CPU-s is its true cost.
CLOCK_TICKS="$(getconf CLK_TCK)"
cpu_ticks() {
  local stat
  read -r -a stat < "/proc/$BASHPID/stat"
  CPU_TICKS=$(( stat[13] + stat[14] + stat[15] + stat[16] ))
}
seconds_since() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'; }
# logged CMD... : run with output to this step's log; on failure show its tail.
logged() {
  if ! "$@" >>"$LOGS/$STEP.log" 2>&1; then
    echo "---- last lines of build/logs/$STEP.log ----" >&2
    tail -n 40 "$LOGS/$STEP.log" >&2
    die "$STEP: '$*' failed (full log: build/logs/$STEP.log)"
  fi
}
# venv_install ARGS... : `uv pip install ARGS` into .venv, one at a time across steps (logged).
# uv (pinned, UV_VERSION) downloads side by side and links from its cache: the ROS 2 wheels
# install in a third of pip's time, cold.
venv_install() { logged flock "$BUILD/.pip.lock" "$VENV/bin/uv" pip install --python "$VENV/bin/python" "$@"; }
# apt_install PACKAGE... : Debian packages, when we may (root); one apt-get at a time.
apt_install() {
  [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1 \
    || die "$STEP needs Debian's $*: sudo apt-get install $*"
  local apt=(apt-get -q -o DPkg::Lock::Timeout=600)
  if ! apt-cache policy "$@" 2>/dev/null | grep -q 'Candidate: [0-9]'; then
    logged flock "$BUILD/.apt.lock" "${apt[@]}" update
  fi
  logged flock "$BUILD/.apt.lock" env DEBIAN_FRONTEND=noninteractive "${apt[@]}" install -y "$@"
}
# wheel_libs: the library folders of the ROS 2 wheels, colon-separated (for LD_LIBRARY_PATH).
wheel_libs() {
  local libs="$PREFIX/lib:$VENV/lib" d
  for d in "$VENV"/lib/python$PYVER/site-packages/ros_*.libs; do libs="$libs:$d"; done
  printf '%s' "$libs"
}
# fresh_build_dir DIR SOURCE: a CMake build dir configured for another checkout path is of no
# use (CMake refuses it).
fresh_build_dir() {
  if [ -f "$1/CMakeCache.txt" ] && ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$2" "$1/CMakeCache.txt"; then
    rm -rf "$1"
  fi
}
# swap_in NEW DEST: replace DEST by NEW through renames. Running cores keep reading the jars
# they started with, so a jar is never overwritten in place.
swap_in() {
  rm -rf "$2.old"
  if [ -d "$2" ]; then mv "$2" "$2.old"; fi
  mv "$1" "$2"
}

# ---------------------------------------------------------------- prerequisites
# One start of each candidate (pyenv shims cost most of a second each): its version, its real
# interpreter (not a shim or a symlink) and whether it can make venvs.
python_info() {
  "$1" -c 'import os, sys
if sys.version_info[:2] != (3, 11):
    sys.exit(3)
try:
    import venv, ensurepip  # noqa: F401
except ImportError:
    sys.exit(4)
print(os.path.realpath(sys.executable))
print(sys.version)' 2>/dev/null
}
PYTHON_INFO=""
for c in ${PYTHON:-python3.11 python3}; do
  command -v "$c" >/dev/null 2>&1 || continue
  rc=0; PYTHON_INFO="$(python_info "$c")" || rc=$?
  [ "$rc" != 4 ] || die "Python $PYVER at $c lacks the venv/ensurepip modules (Debian: apt-get install python3.11-venv)."
  [ "$rc" = 0 ] && break
  PYTHON_INFO=""
done
[ -n "$PYTHON_INFO" ] \
  || die "Python $PYVER is required (the ROS 2 wheels are cp311 only): no python3.11/python3 of version $PYVER found${PYTHON:+ (PYTHON=$PYTHON)}."
PYTHON="${PYTHON_INFO%%$'\n'*}"
PYTHON_VERSION="${PYTHON_INFO#*$'\n'}"

command -v java >/dev/null 2>&1 || die "Java 17 is required: 'java' not found (Debian: apt-get install openjdk-17-jdk-headless)."
JAVA_MAJOR="$(java -version 2>&1 | sed -n 's/.*version "\([0-9][0-9]*\)\(\.\([0-9][0-9]*\)\)\{0,1\}.*/\1 \3/p' | head -n1)"
case "$JAVA_MAJOR" in 1\ *) JAVA_MAJOR="${JAVA_MAJOR#1 }" ;; *) JAVA_MAJOR="${JAVA_MAJOR%% *}" ;; esac
[ -n "$JAVA_MAJOR" ] && [ "$JAVA_MAJOR" -ge 17 ] 2>/dev/null \
  || die "Java 17 is required: 'java -version' reports '$(java -version 2>&1 | head -n1)'."
command -v mvn >/dev/null 2>&1 || die "Maven is required: 'mvn' not found (Debian: apt-get install maven)."
SYSTEM_MAVEN_HOME="$(dirname "$(dirname "$(readlink -f "$(command -v mvn)")")")"
for t in cmake make g++; do
  command -v "$t" >/dev/null 2>&1 || die "'$t' is required to build armor_msgs (Debian: apt-get install cmake build-essential)."
done
command -v flock >/dev/null 2>&1 || die "'flock' is required (Debian: apt-get install util-linux)."

mkdir -p "$STAMPS" "$LOGS"

# Bump a step's LOGIC when what it does changes, so stamps made by an older script are redone.
VENV_LOGIC=4
UV_VERSION=0.13.9
VENV_HASH="$(hash_str "$VENV_LOGIC" "$UV_VERSION" "$ROOT" "$PYTHON" "$PYTHON_VERSION" "$(hash_of tools/requirements-ros2.txt)")"
MSGS_LOGIC=2
# MSGS_HASH is set once the steps to run are known (it holds whether C++ is built).

# ---------------------------------------------------------------- venv
venv_ok() { [ -x "$VENV/bin/python" ] && "$VENV/bin/python" -c pass >/dev/null 2>&1; }
step_venv() {
  up_to_date "$VENV_HASH" venv_ok && return
  begin "installing $(grep -c '==' tools/requirements-ros2.txt) pinned packages (ROS 2 wheels) into .venv"
  # Reuse a venv of the same Python made at this path (venvs do not survive a move).
  local shebang
  shebang="$(head -n1 "$VENV/bin/pip" 2>/dev/null || true)"
  if ! { venv_ok && [ "${shebang#"#!$VENV/bin/python"}" != "$shebang" ] \
         && [ "$("$VENV/bin/python" -c 'import sys; print(sys.version)' 2>/dev/null)" = "$PYTHON_VERSION" ]; }; then
    rm -rf "$VENV"
    logged "$PYTHON" -m venv --without-pip "$VENV"
    # A new venv holds none of what the steps after this one installed into the old one.
    local name
    for name in "${STEP_NAMES[@]}"; do
      case " ${STEP_NEEDS[$name]} " in *" venv "*) rm -f "$STAMPS/$name" ;; esac
    done
  fi
  # uv installs the packages (pip itself among them, pinned); uv is put into the venv by the pip
  # wheel that ensurepip carries, run from the wheel: a venv made with its own pip cost 7-9
  # CPU-s of ensurepip on the way to "ARMOR ready". Debian keeps that wheel elsewhere; without
  # one, ensurepip after all.
  local pip_wheel
  pip_wheel="$("$PYTHON" - <<'EOF'
import ensurepip, glob, os, sysconfig
places = [os.path.join(os.path.dirname(ensurepip.__file__), '_bundled'),
          sysconfig.get_config_var('WHEEL_PKG_DIR') or '', '/usr/share/python-wheels']
wheels = sorted(w for place in places if place for w in glob.glob(os.path.join(place, 'pip-*.whl')))
print(wheels[-1] if wheels else '')
EOF
)"
  if [ -n "$pip_wheel" ]; then
    logged flock "$BUILD/.pip.lock" "$VENV/bin/python" "$pip_wheel/pip" install --no-compile "uv==$UV_VERSION"
  else
    logged flock "$BUILD/.pip.lock" sh -c '"$1" -m ensurepip && "$1" -m pip install --no-compile "uv==$2"' \
      _ "$VENV/bin/python" "$UV_VERSION"
  fi
  venv_install -r tools/requirements-ros2.txt
  # Exported CMake files of some wheels name the wheel build host's Python; point them here.
  local inc sp
  inc="$("$VENV/bin/python" -c "import sysconfig; print(sysconfig.get_paths()['include'])")"
  sp="$("$VENV/bin/python" -c "import sysconfig; print(sysconfig.get_paths()['purelib'])")"
  { grep -l '/opt/python/cp311-cp311' "$VENV"/share/*/cmake/*Export.cmake 2>/dev/null || true; } \
    | while IFS= read -r f; do
        sed -i "s#/opt/python/cp311-cp311/include/python3.11#$inc#g; s#/opt/python/cp311-cp311/lib/python3.11/site-packages#$sp#g" "$f"
      done
  done_in "$VENV_HASH" "installed $(grep -c '==' tools/requirements-ros2.txt) pinned packages"
}

# pip_requirements FILE... : a step that pip-installs pinned requirements into .venv.
pip_requirements() {
  local hash
  hash="$(hash_str "$VENV_HASH" "$(hash_of "$@")")"
  up_to_date "$hash" && return
  begin "installing $(cat "$@" | grep -c '==') pinned packages of $*"
  local args=() f
  for f in "$@"; do args+=(-r "$f"); done
  venv_install "${args[@]}"
  done_in "$hash" "installed"
}
step_lint() { pip_requirements tools/requirements-lint.txt; }
step_planner() { pip_requirements tools/requirements-planning.txt; }
step_colcon() { pip_requirements tools/requirements-colcon.txt; }
step_testrunner() { pip_requirements tools/requirements-test-runner.txt; }

# The clock-jump test (tests/integration/test_clock_jumps.py) moves the wall clock of a running
# node and core with libfaketime.
FAKETIME_LIB=/usr/lib/x86_64-linux-gnu/faketime/libfaketime.so.1
step_faketime() {
  up_to_date libfaketime test -f "$FAKETIME_LIB" && return
  begin "installing Debian's libfaketime"
  apt_install libfaketime
  done_in libfaketime "installed"
}

# ---------------------------------------------------------------- web view
# The page's graph library, from the npm registry (its integrity checked), kept out of git.
CYTOSCAPE_VERSION=3.34.4
CYTOSCAPE_SHA512='msY99tMY8iWTg+sIPGfSqDcPNOt4xcj+v/K/7qUFaCUxxlqnMkUYLBjRUzn9W5CU/R2hrmtJa5+UtovrEM2ctg=='
VENDOR="$ROOT/armor_service/armor_service/web/static/vendor"
step_web() {
  local hash
  hash="$(hash_str "$VENV_HASH" "$(hash_of tools/requirements-web.txt)" "$CYTOSCAPE_VERSION" "$CYTOSCAPE_SHA512")"
  up_to_date "$hash" test -f "$VENDOR/cytoscape.min.js" && return
  begin "installing aiohttp (pinned) and cytoscape.js $CYTOSCAPE_VERSION"
  command -v npm >/dev/null 2>&1 \
    || die "npm is required to fetch the web view's graph library cytoscape.js (Debian: apt-get install npm)."
  venv_install -r tools/requirements-web.txt
  local pack_dir tarball
  pack_dir="$(mktemp -d)"
  (cd "$pack_dir" && logged npm pack --silent "cytoscape@$CYTOSCAPE_VERSION")
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
  done_in "$hash" "installed"
}

# The web view's real-browser tests drive Debian's chromium: Playwright's own browser download
# cannot work on a machine that reaches only package registries.
step_browser() {
  local hash
  hash="$(hash_str "$VENV_HASH" "$(hash_of tools/requirements-browser-tests.txt)")"
  up_to_date "$hash" command -v chromium && return
  begin "installing Playwright (pinned) and Debian's chromium where missing"
  venv_install -r tools/requirements-browser-tests.txt
  command -v chromium >/dev/null 2>&1 || apt_install chromium
  done_in "$hash" "installed"
}

# ---------------------------------------------------------------- armor_msgs
# The Python node needs only the C messages, their C typesupports and the Python bindings;
# the C++ code and typesupports (half of the compile) are built when the C++ client is
# (MSGS_CPP, below), and kept from then on.
step_armor_msgs() {
  up_to_date "$MSGS_HASH" test -d "$PREFIX/lib/python$PYVER/site-packages/armor_msgs" && return
  begin "generating and compiling armor_msgs for C and Python$([ "$MSGS_CPP" = ON ] && echo ' and C++') with cmake and make"
  fresh_build_dir "$BUILD/armor_msgs" "$ROOT/armor_msgs"
  export AMENT_PREFIX_PATH="$VENV"
  logged cmake -S armor_msgs -B "$BUILD/armor_msgs" \
    -DCMAKE_PREFIX_PATH="$VENV" -DCMAKE_INSTALL_PREFIX="$PREFIX" \
    -DPython3_EXECUTABLE="$VENV/bin/python" -DBUILD_TESTING=OFF -DWITH_CPP_TYPESUPPORT="$MSGS_CPP"
  logged make -C "$BUILD/armor_msgs" -j"$(nproc)"
  rm -rf "$PREFIX"   # no stale files from removed interfaces
  logged make -C "$BUILD/armor_msgs" install
  done_in "$MSGS_HASH" "built"
}

# ---------------------------------------------------------------- armor_cpp (C++ client)
# Its GoogleTest tests are built with PART test (Debian's libgtest-dev, installed when missing).
CPP_LOGIC=2
CPP_PREFIX="$ROOT/install/armor_cpp"
have_gtest() {
  [ -f /usr/lib/x86_64-linux-gnu/cmake/GTest/GTestConfig.cmake ] || [ -f /usr/lib/cmake/GTest/GTestConfig.cmake ]
}
cpp_built() {
  [ -f "$CPP_PREFIX/lib/libarmor_cpp.so" ] && { [ "$CPP_TESTS" = OFF ] || [ -x "$BUILD/armor_cpp/armor_cpp_live_test" ]; }
}
step_cpp() {
  local hash
  hash="$(hash_str "$CPP_LOGIC" "$CPP_TESTS" "$MSGS_HASH" \
    "$(hash_tree armor_cpp/include armor_cpp/src armor_cpp/test armor_cpp/examples armor_cpp/bench)" \
    "$(hash_of armor_cpp/CMakeLists.txt armor_cpp/package.xml)")"
  up_to_date "$hash" cpp_built && return
  begin "compiling the C++ client$([ "$CPP_TESTS" = ON ] && echo ' and its tests') with cmake and make"
  if [ "$CPP_TESTS" = ON ] && ! have_gtest; then apt_install libgtest-dev; fi
  fresh_build_dir "$BUILD/armor_cpp" "$ROOT/armor_cpp"
  export AMENT_PREFIX_PATH="$PREFIX:$VENV"
  logged cmake -S armor_cpp -B "$BUILD/armor_cpp" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$PREFIX;$VENV" -DCMAKE_INSTALL_PREFIX="$CPP_PREFIX" \
    -DPython3_EXECUTABLE="$VENV/bin/python" -DBUILD_TESTING="$CPP_TESTS"
  # The wheels' libraries find each other (and their bundled copies of tinyxml2, OpenSSL...
  # in ros_*.libs) through LD_LIBRARY_PATH, as install/setup.sh sets it; so does the linker.
  LD_LIBRARY_PATH="$(wheel_libs)${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    logged make -C "$BUILD/armor_cpp" -j"$(nproc)"
  rm -rf "$CPP_PREFIX"
  logged make -C "$BUILD/armor_cpp" install
  done_in "$hash" "built"
}

# ---------------------------------------------------------------- scenes (SIT)
# The scene service's interface package sit_armor_injected_msgs (cmake + make, as armor_msgs) and
# the node extension serving it (sit_armor_injected/, editable), both into the venv's prefix, so
# install/setup.bash needs no line for them. A reinstall first removes what the last one
# installed (CMake's install manifest). Only the node (Python) uses these messages: no C++ code.
SIT_LOGIC=4
step_scenes() {
  local hash build="$BUILD/sit_armor_injected_msgs"
  hash="$(hash_str "$SIT_LOGIC" "$VENV_HASH" "$ROOT" \
    "$(hash_tree sit_armor_injected_msgs/msg sit_armor_injected_msgs/srv)" \
    "$(hash_of sit_armor_injected_msgs/package.xml sit_armor_injected_msgs/CMakeLists.txt \
      sit_armor_injected/setup.py sit_armor_injected/package.xml)")"
  scenes_installed() {
    [ -d "$VENV/lib/python$PYVER/site-packages/sit_armor_injected_msgs" ] \
      && "$VENV/bin/python" -c 'import sit_armor_injected' >/dev/null 2>&1
  }
  up_to_date "$hash" scenes_installed && return
  begin "building sit_armor_injected_msgs (C and Python) with cmake and make, installing the scene extension"
  fresh_build_dir "$build" "$ROOT/sit_armor_injected_msgs"
  logged env AMENT_PREFIX_PATH="$VENV" cmake -S sit_armor_injected_msgs -B "$build" \
    -DCMAKE_PREFIX_PATH="$VENV" -DCMAKE_INSTALL_PREFIX="$VENV" \
    -DPython3_EXECUTABLE="$VENV/bin/python" -DBUILD_TESTING=OFF -DWITH_CPP_TYPESUPPORT=OFF
  logged env AMENT_PREFIX_PATH="$VENV" make -C "$build" -j"$(nproc)"
  if [ -f "$build/install_manifest.txt" ]; then
    # No stale files from removed interfaces (only paths inside the venv are touched).
    grep "^$VENV/" "$build/install_manifest.txt" | while IFS= read -r f; do rm -f "$f"; done
  fi
  # Under the pip lock: a pip run of another step that lists the venv while this writes
  # its egg-info read a half-written one ("Invalid version: None") and failed. The egg-info of
  # an earlier version goes first: emptied by the removal above, it broke every later pip run.
  logged flock "$BUILD/.pip.lock" sh -c 'rm -rf "$1"/sit_armor_injected_msgs-*.egg-info && make -C "$2" install' \
    _ "$VENV/lib/python$PYVER/site-packages" "$build"
  venv_install --no-deps --no-build-isolation --config-settings editable_mode=compat -e sit_armor_injected
  done_in "$hash" "built"
}

# ---------------------------------------------------------------- Maven (pinned)
# The Java steps use this Maven, not the system's: Maven 3.9's resolver collects a project's
# dependency graph several POMs at a time (breadth first), where Debian's 3.8.7 asks for one
# POM after the other, which made the cold build of the core take 127 s on an idle machine.
# It comes from the Maven Central that the installed Maven uses (the repository its super POM
# names) and must have the pinned SHA-512; when it cannot be had, the step fails: there is no
# quiet fallback to another Maven. `mvn` on the PATH stays the system's.
MAVEN_VERSION=3.9.16
MAVEN_SHA512=831a8591fe20c8243b1dbe7d71e3244f31d1665b0804b2e825e38cbbe5ce0cafb8338851f90780735568773e0a6cd07bbec107cda0b896b008b861075358b6f6
MAVEN_HOME="$BUILD/maven/apache-maven-$MAVEN_VERSION"
# -B -q: no colours or progress in the logs. The breadth-first collector fetches POMs in
# parallel (Maven 3.9 still collects depth first by default); more download threads than 5
# for the jars themselves.
MVN=("$MAVEN_HOME/bin/mvn" -B -q -Daether.dependencyCollector.impl=bf -Daether.connector.basic.threads=8)
# Maven's own JVM takes its options from .mvn/jvm.config (found above core/ and plugins/*/): a
# build is too short for the optimising JIT to pay back; with C1 alone and the serial GC it
# built the core in 12 CPU-s instead of 32 (and in half the wall time).
step_maven() {
  up_to_date "$MAVEN_VERSION $MAVEN_SHA512" test -x "$MAVEN_HOME/bin/mvn" && return
  begin "downloading Maven $MAVEN_VERSION (pinned SHA-512) from Maven Central"
  rm -rf "$BUILD/maven"
  mkdir -p "$BUILD/maven"
  logged "$PYTHON" - "$SYSTEM_MAVEN_HOME" "$MAVEN_VERSION" "$MAVEN_SHA512" "$BUILD/maven/dist.tar.gz" <<'EOF'
import glob, hashlib, os, re, sys, urllib.request, zipfile
system_home, version, sha512, target = sys.argv[1:]
# Maven Central's address, as the installed Maven has it (the super POM's repository).
jar = sorted(glob.glob(os.path.join(system_home, 'lib', 'maven-model-builder*.jar')))[0]
with zipfile.ZipFile(jar) as model_builder:
    super_pom = model_builder.read('org/apache/maven/model/pom-4.0.0.xml').decode()
central = re.search(r'<url>([^<]+)</url>', super_pom).group(1).rstrip('/')
url = f'{central}/org/apache/maven/apache-maven/{version}/apache-maven-{version}-bin.tar.gz'
print('fetching', url)
with urllib.request.urlopen(url, timeout=120) as answer:
    data = answer.read()
got = hashlib.sha512(data).hexdigest()
if got != sha512:
    sys.exit(f'{url}: SHA-512 {got}, not the pinned {sha512}')
with open(target, 'wb') as out:
    out.write(data)
EOF
  logged tar -xzf "$BUILD/maven/dist.tar.gz" -C "$BUILD/maven"
  rm -f "$BUILD/maven/dist.tar.gz"
  done_in "$MAVEN_VERSION $MAVEN_SHA512" "installed Maven $MAVEN_VERSION into build/maven"
}

# ---------------------------------------------------------------- core (Java)
step_core() {
  local hash
  hash="$(hash_str "$(hash_of core/pom.xml)" "$(hash_tree core/src)")"
  up_to_date "$hash" test -f install/armor_core/armor-core.jar && return
  begin "building the Java core with Maven; the first run downloads its libraries"
  # The tests are compiled by make test (mvn test), not on the way to "ARMOR ready".
  logged "${MVN[@]}" -f core/pom.xml package -Dmaven.test.skip=true
  rm -rf install/armor_core.new
  mkdir -p install/armor_core.new
  cp -r core/target/armor-core.jar core/target/lib install/armor_core.new/
  swap_in install/armor_core.new install/armor_core
  done_in "$hash" "built"
}

# The archive (tools/core_archive.py) is made for one jar and one JDK: a new jar (a new
# install/armor_core, without the archive) or another java makes a new one. A JVM given an
# archive that does not match ignores it (core_process.py), so a stale one only costs time.
ARCHIVE_LOGIC=1
step_archive() {
  local jar="$ROOT/install/armor_core/armor-core.jar" archive="$ROOT/install/armor_core/armor-core.jsa"
  local hash
  hash="$(hash_str "$ARCHIVE_LOGIC" "$(hash_of "$jar" tools/core_archive.py ontologies/robotics.owl)" \
    "$(stat -c %Y "$jar")" "$(readlink -f "$(command -v java)")" "$(java -version 2>&1)")"
  up_to_date "$hash" test -f "$archive" && return
  begin "recording the classes a short core session loads into install/armor_core/armor-core.jsa"
  rm -f "$archive" "$archive.new"
  logged "$PYTHON" tools/core_archive.py "$jar" "$archive.new"
  mv "$archive.new" "$archive"
  done_in "$hash" "archived $(( $(stat -c %s "$archive") >> 20 )) MB of classes"
}

# ---------------------------------------------------------------- plugins (Java)
# Each plugins/<name>/pom.xml builds a jar for the core's plugin directories, compiled against
# the installed core; the jars and their own libraries go to install/armor_plugins, which the
# node loads by default (plugin_dirs defaults to $ARMOR_PLUGIN_DIRS, exported by install/setup.sh).
# All plugins are built in one Maven run (a reactor made in build/plugins naming each of them):
# one start of Maven and one resolution of the build plugins, instead of one per plugin.
PLUGINS_LOGIC=3
step_plugins() {
  local poms
  poms="$(ls plugins/*/pom.xml 2>/dev/null || true)"
  if [ -z "$poms" ]; then echo "plugins: none"; return; fi
  local hash
  # shellcheck disable=SC2086
  hash="$(hash_str "$PLUGINS_LOGIC" "$(hash_of install/armor_core/armor-core.jar $poms)" "$(hash_tree plugins/*/src)")"
  up_to_date "$hash" test -d install/armor_plugins && return
  begin "building the core's plugins ($(echo $poms | xargs -n1 dirname | xargs -n1 basename | tr '\n' ' ' | sed 's/ $//')) with Maven"
  local pom dir modules=""
  for pom in $poms; do modules="$modules<module>../../$(dirname "$pom")</module>"; done
  mkdir -p "$BUILD/plugins"
  cat > "$BUILD/plugins/pom.xml" <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<!-- Generated by tools/setup.sh: every plugins/*/pom.xml, built in one Maven run. -->
<project xmlns="http://maven.apache.org/POM/4.0.0">
  <modelVersion>4.0.0</modelVersion>
  <groupId>io.github.armor-ros2</groupId>
  <artifactId>armor-plugins-reactor</artifactId>
  <version>0</version>
  <packaging>pom</packaging>
  <modules>$modules</modules>
</project>
EOF
  # clean: a resource renamed or deleted in src (a services file) must not linger in the jar.
  logged "${MVN[@]}" -f "$BUILD/plugins/pom.xml" clean package -Dmaven.test.skip=true \
    -Dcore.jar="$ROOT/install/armor_core/armor-core.jar"
  rm -rf install/armor_plugins.new
  mkdir -p install/armor_plugins.new
  for pom in $poms; do
    dir="$(dirname "$pom")"
    cp "$dir"/target/*.jar install/armor_plugins.new/
    if [ -d "$dir/target/lib" ]; then cp "$dir"/target/lib/*.jar install/armor_plugins.new/; fi
  done
  swap_in install/armor_plugins.new install/armor_plugins
  done_in "$hash" "built $(ls install/armor_plugins | tr '\n' ' ')"
}

# ---------------------------------------------------------------- Python packages
# editable_mode=compat: a .pth entry for <pkg>/ instead of setuptools' import-hook finder.
# With the finder, running Python from the repo root imports the outer folder armor_client/
# (no __init__.py) as a namespace package; a real path entry wins over it.
PY_LOGIC=3
PY_PACKAGES=(armor_contract armor_service armor_client)
step_python() {
  local hash pkg files=()
  for pkg in "${PY_PACKAGES[@]}"; do files+=("$pkg/setup.py" "$pkg/setup.cfg" "$pkg/package.xml"); done
  hash="$(hash_str "$PY_LOGIC" "$VENV_HASH" "$ROOT" "$(hash_of "${files[@]}")")"
  up_to_date "$hash" && return
  begin "installing ${PY_PACKAGES[*]} in editable mode"
  local editable=()
  for pkg in "${PY_PACKAGES[@]}"; do editable+=(-e "$pkg"); done
  venv_install --no-deps --no-build-isolation --config-settings editable_mode=compat "${editable[@]}"
  # Editable wheels leave out setup.py's data_files (ament index marker, package.xml, ...):
  # symlink them into the venv prefix, as colcon's --symlink-install would.
  for pkg in "${PY_PACKAGES[@]}"; do
    logged "$VENV/bin/python" - "$pkg" "$STAMPS/$pkg.data" <<'EOF'
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
  done
  done_in "$hash" "installed"
}

# ---------------------------------------------------------------- install/setup.bash, setup.sh
# install/setup.sh holds the environment for POSIX sh (with this checkout's absolute path):
# the ROS 2 of the wheels in .venv, then armor_msgs, the C++ client, the core and its plugins.
# install/underlay.sh holds only the first part: what /opt/ros/<distro>/setup.sh is on a
# machine with ROS 2 installed, to source before `colcon build` of a workspace holding this
# repository. setup.bash finds its own checkout through BASH_SOURCE and sources setup.sh.
step_env() {
  local prepend underlay overlay cleanup bash_body setup_sh underlay_sh setup_bash hash
  read -r -d '' prepend <<'EOF' || true
: "${_armor_root:=@ROOT@}"
_armor_venv="$_armor_root/.venv"

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
EOF
  read -r -d '' underlay <<'EOF' || true
# ROS 2 from the wheels in .venv. Console scripts: ament_python packages may put theirs in lib/<pkg>.
for _armor_d in "$_armor_venv/lib/armor_client" "$_armor_venv/lib/armor_service"; do
  if [ -d "$_armor_d" ]; then _armor_prepend PATH "$_armor_d"; fi
done
_armor_prepend PATH "$_armor_venv/bin"
# What the ros_wheels_bootstrapper .pth would add by re-executing every Python start;
# with these set, its guard variable spares that re-exec.
for _armor_d in "$_armor_venv"/lib/python@PYVER@/site-packages/ros_*.libs; do
  if [ -d "$_armor_d" ]; then _armor_prepend LD_LIBRARY_PATH "$_armor_d"; fi
done
_armor_prepend LD_LIBRARY_PATH "$_armor_venv/lib"
_ROS_WHEELS_BOOTSTRAP_COMPLETE=1
_armor_prepend AMENT_PREFIX_PATH "$_armor_venv"
_armor_prepend CMAKE_PREFIX_PATH "$_armor_venv"
RMW_IMPLEMENTATION=rmw_fastrtps_cpp
# DDS discovery stays on this host unless the caller chose otherwise.
: "${ROS_AUTOMATIC_DISCOVERY_RANGE:=LOCALHOST}"
export _ROS_WHEELS_BOOTSTRAP_COMPLETE RMW_IMPLEMENTATION ROS_AUTOMATIC_DISCOVERY_RANGE
EOF
  read -r -d '' overlay <<'EOF' || true
# ARMOR as tools/setup.sh built it in this checkout.
_armor_prefix="$_armor_root/install/armor_msgs"
_armor_prepend PYTHONPATH "$_armor_prefix/lib/python@PYVER@/site-packages"
_armor_prepend LD_LIBRARY_PATH "$_armor_prefix/lib"
_armor_prepend LD_LIBRARY_PATH "$_armor_root/install/armor_cpp/lib"
_armor_prepend AMENT_PREFIX_PATH "$_armor_prefix"
_armor_prepend CMAKE_PREFIX_PATH "$_armor_prefix"
_armor_prepend CMAKE_PREFIX_PATH "$_armor_root/install/armor_cpp"
ARMOR_CORE_JAR="$_armor_root/install/armor_core/armor-core.jar"
# The plugins make setup built (the node's default plugin_dirs).
ARMOR_PLUGIN_DIRS="$_armor_root/install/armor_plugins"
export ARMOR_CORE_JAR ARMOR_PLUGIN_DIRS
EOF
  read -r -d '' cleanup <<'EOF' || true
unset _armor_root _armor_venv _armor_prefix _armor_old _armor_new _armor_ifs _armor_p _armor_d
unset -f _armor_prepend
EOF
  read -r -d '' bash_body <<'EOF' || true
# Environment of ARMOR for ROS 2. Generated by tools/setup.sh: do not edit.
# Source it from anywhere: source /path/to/checkout/install/setup.bash
if [ -n "${BASH_SOURCE[0]:-}" ]; then
  _armor_root="$(CDPATH='' cd -- "$(dirname -- "${BASH_SOURCE[0]}")/.." && pwd)"
else
  _armor_root="@ROOT@"
fi
. "$_armor_root/install/setup.sh"
EOF
  setup_sh="# Environment of ARMOR for ROS 2. Generated by tools/setup.sh: do not edit.
# Source it: . install/setup.sh   (POSIX sh; bash users: source install/setup.bash)
$prepend
$underlay
$overlay
$cleanup"
  underlay_sh="# ROS 2 of this checkout (the pinned wheels in .venv), without ARMOR's own packages.
# Generated by tools/setup.sh: do not edit. What /opt/ros/<distro>/setup.sh is on a machine
# with ROS 2 installed: source it before \`colcon build\` of a workspace holding this repository.
$prepend
$underlay
$cleanup"
  setup_sh="${setup_sh//@ROOT@/$ROOT}"; setup_sh="${setup_sh//@PYVER@/$PYVER}"
  underlay_sh="${underlay_sh//@ROOT@/$ROOT}"; underlay_sh="${underlay_sh//@PYVER@/$PYVER}"
  setup_bash="${bash_body//@ROOT@/$ROOT}"
  hash="$(hash_str "$setup_sh" "$underlay_sh" "$setup_bash")"
  written() {
    [ "$(hash_str "$(cat install/setup.sh)" "$(cat install/underlay.sh)" "$(cat install/setup.bash)")" = "$hash" ]
  }
  up_to_date "$hash" written 2>/dev/null && return
  mkdir -p install
  printf '%s\n' "$setup_sh" > install/setup.sh
  printf '%s\n' "$underlay_sh" > install/underlay.sh
  printf '%s\n' "$setup_bash" > install/setup.bash
  printf '%s\n' "$hash" > "$STAMPS/env"
  echo "env: wrote install/setup.bash, install/setup.sh and install/underlay.sh"
}

# ---------------------------------------------------------------- what to run
usage() {
  echo "usage: bash tools/setup.sh [PART...]   PART: test, or a step's name (--name works too)"
  local s
  for s in "${STEP_NAMES[@]}"; do
    printf '  %-11s %-5s %s\n' "$s" "${STEP_GROUP[$s]}" "${STEP_WHAT[$s]}"
  done
}
declare -A WANTED
want() {
  local need
  [ -n "${WANTED[$1]:-}" ] && return
  WANTED[$1]=1
  for need in ${STEP_NEEDS[$1]}; do want "$need"; done
}
CPP_TESTS=OFF
for s in "${STEP_NAMES[@]}"; do [ "${STEP_GROUP[$s]}" = run ] && want "$s"; done
for part in "$@"; do
  part="${part#--}"
  case "$part" in
    list|help|h) usage; exit 0 ;;
    test) CPP_TESTS=ON
          for s in "${STEP_NAMES[@]}"; do [ "${STEP_GROUP[$s]}" = test ] && want "$s"; done ;;
    *) [ -n "${STEP_GROUP[$part]:-}" ] || { usage >&2; die "no step or group named '$part'"; }
       want "$part" ;;
  esac
done

# A C++ build made with its tests keeps them (make cpp after make test rebuilds nothing).
if grep -qx 'BUILD_TESTING:BOOL=ON' "$BUILD/armor_cpp/CMakeCache.txt" 2>/dev/null; then CPP_TESTS=ON; fi
# armor_msgs with its C++ code when the C++ client is built now or was (make run after make
# test rebuilds nothing, and never takes away what the installed client links).
MSGS_CPP=OFF
if [ -n "${WANTED[cpp]:-}" ] || [ -e "$CPP_PREFIX/lib/libarmor_cpp.so" ] \
   || grep -qx 'WITH_CPP_TYPESUPPORT:BOOL=ON' "$BUILD/armor_msgs/CMakeCache.txt" 2>/dev/null; then
  MSGS_CPP=ON
fi
MSGS_HASH="$(hash_str "$MSGS_LOGIC" "$MSGS_CPP" "$VENV_HASH" "$ROOT" \
  "$(hash_tree armor_msgs/msg armor_msgs/srv)" "$(hash_of armor_msgs/package.xml armor_msgs/CMakeLists.txt)")"

# Start every wanted step whose needs are done; on a failure start nothing more, let the
# running steps end, and fail.
declare -A STATE PID_STEP
T_SETUP=$EPOCHREALTIME
failed=""
running=0
while :; do
  if [ -z "$failed" ]; then
    for s in "${STEP_NAMES[@]}"; do
      [ -n "${WANTED[$s]:-}" ] && [ -z "${STATE[$s]:-}" ] || continue
      ready=1
      for need in ${STEP_NEEDS[$s]}; do [ "${STATE[$need]:-}" = done ] || ready=""; done
      [ -n "$ready" ] || continue
      STEP="$s" "step_$s" &
      PID_STEP[$!]=$s; STATE[$s]=running; running=$((running + 1))
    done
  fi
  [ "$running" -gt 0 ] || break
  pid=""
  if wait -n -p pid; then rc=0; else rc=$?; fi
  [ -n "$pid" ] || die "lost track of the running steps"
  s="${PID_STEP[$pid]}"; running=$((running - 1))
  if [ "$rc" = 0 ]; then STATE[$s]=done; else STATE[$s]=failed; failed="$failed $s"; fi
done
[ -z "$failed" ] || die "step(s)$failed failed; see above"
for s in "${STEP_NAMES[@]}"; do
  [ -z "${WANTED[$s]:-}" ] || [ "${STATE[$s]:-}" = done ] \
    || die "step $s did not run: a step it needs is missing"
done
echo "setup: done in $(seconds_since "$T_SETUP") s; source $ROOT/install/setup.bash"

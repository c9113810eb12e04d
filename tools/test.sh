#!/usr/bin/env bash
# The whole test suite: the core's JUnit tests, then the Python tests, which start the real
# node in its own process and call it over ROS 2. Run through `make test` (which sets up first).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
source install/setup.bash
# Imports may cache their bytecode (see tools/setup.sh): with PYTHONDONTWRITEBYTECODE set, each
# of the suite's processes (nodes, CLI calls, workers) compiled rclpy, numpy and ARMOR's modules
# again, 0.6 CPU-s per process.
unset PYTHONDONTWRITEBYTECODE

echo "== core: JUnit (Maven Surefire)"
mvn -B -q -f core/pom.xml test
for pom in plugins/*/pom.xml; do
  [ -f "$pom" ] || continue
  echo "== plugin $(dirname "$pom"): JUnit against the installed core"
  mvn -B -q -f "$pom" test -Dcore.jar="$root/install/armor_core/armor-core.jar"
done
python3 - <<'PY'
import glob, xml.etree.ElementTree as ET
runs = failures = errors = skipped = 0
for report in glob.glob('core/target/surefire-reports/TEST-*.xml') + glob.glob(
        'plugins/*/target/surefire-reports/TEST-*.xml'):
    suite = ET.parse(report).getroot()
    runs += int(suite.get('tests')); failures += int(suite.get('failures'))
    errors += int(suite.get('errors')); skipped += int(suite.get('skipped'))
print(f'core and plugins: Tests run: {runs}, Failures: {failures}, Errors: {errors}, Skipped: {skipped}')
PY

echo "== C++ client: GoogleTest without a node (ctest; its live tests run under pytest)"
ctest --test-dir build/armor_cpp --output-on-failure --output-junit ctest-junit.xml
# ctest counts a case that skipped itself (GTEST_SKIP) as not run and still exits 0: here a
# skipped case is no pass.
python3 - <<'PY'
import xml.etree.ElementTree as ET
cases = list(ET.parse('build/armor_cpp/ctest-junit.xml').getroot().iter('testcase'))
skipped = [case.get('name') for case in cases if case.find('skipped') is not None]
if skipped:
    raise SystemExit(f'C++ client: {len(skipped)} of {len(cases)} GoogleTest cases skipped, '
                     'which is no pass: ' + ', '.join(skipped))
print(f'C++ client: {len(cases)} GoogleTest cases passed, none skipped')
PY

# Test files run side by side, ARMOR_TEST_WORKERS at a time (3 by default: most of a file's time
# is spent waiting for ROS discovery, restarts and reasoners, so 3 keep 2 cores busy). Each
# worker reserves its own DDS domain and starts its own nodes; a file stays on one worker, so
# its module fixtures start once. Files are taken in the order the suite gives them (the longest
# first, see runs_for_minutes): xdist's default reorder by test count started the 1-test files
# that run for minutes last. ARMOR_TEST_WORKERS=0 runs them one after the other.
workers="${ARMOR_TEST_WORKERS:-3}"
echo "== node, client and CLI: pytest over ROS 2 ($workers files at a time)"
if [ "$workers" = 0 ]; then
  python -m pytest -p no:cacheprovider "$@"
else
  python -m pytest -p no:cacheprovider --numprocesses "$workers" --dist loadfile \
    --no-loadscope-reorder "$@"
fi

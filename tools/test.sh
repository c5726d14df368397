#!/usr/bin/env bash
# Install everything the test suite needs on a fresh Debian machine, then run all of it:
# lint, types, tests, and every benchmark once (timing disabled, counts still asserted).
set -euo pipefail
cd "$(dirname "$0")/.."

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
# ros-core: a real ROS 1 master (roscore) for the tests of `teleop-ui watch`.
if ! command -v roscore >/dev/null 2>&1; then
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends ros-core
fi

python3 -m pip install -q -e '.[test,xacro]'
python3 -m ruff check solver tests benchmarks tools
python3 -m mypy
python3 -m pytest tests benchmarks --benchmark-disable "$@"

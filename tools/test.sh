#!/usr/bin/env bash
# Install everything the test suite needs on a fresh Debian/Ubuntu machine, then run all of it:
# lint, types, tests, and every benchmark once (timing disabled, counts still asserted).
# Python packages go into a project venv (.venv, or $VENV): Debian 12 and Ubuntu 24.04 refuse
# `pip install` into the system interpreter (PEP 668, externally-managed-environment), and a
# venv leaves the system's Python, and ROS's, untouched.
set -euo pipefail
cd "$(dirname "$0")/.."
venv="${VENV:-.venv}"

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
apt_get() {
  # apt-get that waits, up to 10 minutes, for a package manager busy elsewhere (a fresh Ubuntu
  # runs its automatic updates at boot) instead of failing at once. `install` waits by itself
  # (DPkg::Lock::Timeout); `update` takes the package lists' lock, which that option does not
  # cover, so it is tried again every 5 seconds while another process holds that lock.
  local log waited=0
  log="$(mktemp)"
  until $sudo env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 "$@" \
      2>"$log"; do
    cat "$log" >&2
    if ! grep -q "Could not get lock" "$log" || [ "$waited" -ge 600 ]; then
      rm -f "$log"
      return 1
    fi
    [ "$waited" -gt 0 ] || echo "tools/test.sh: another package manager is busy; waiting" >&2
    sleep 5
    waited=$((waited + 5))
  done
  cat "$log" >&2
  rm -f "$log"
}
apt_updated=""
apt_install() {
  # Says what it installs and why before it does: $1 is the reason, the rest the packages.
  local why="$1"; shift
  echo "tools/test.sh: installing Debian packages $* ($why)" >&2
  [ -n "$apt_updated" ] || { apt_get update -q; apt_updated=1; }
  apt_get install -y -q --no-install-recommends "$@"
}

# ros-core: a real ROS 1 master (roscore) for the tests of `teleop-ui watch`.
if ! command -v roscore >/dev/null 2>&1; then
  apt_install "a real ROS 1 master, roscore, for the live tests of watch and assign --master" \
    ros-core
fi

# chromium: tests/layouts/test_preview.py screenshots the layout previews in headless Chromium;
# tests/studio drive it through Playwright (the test extra) at /usr/bin/chromium, never a
# browser Playwright would download.
if ! command -v chromium >/dev/null 2>&1; then
  apt_install "headless Chromium, for the tests of what a person looks at (layout previews, \
report thumbnails, the studio)" chromium chromium-driver
fi

# node and npm: the follower extension for Lichtblick (viewer/lichtblick, issue 38) is
# TypeScript, built with tsc and unit-tested with node's own test runner. Debian 12's nodejs (18)
# and npm are enough.
if ! command -v npm >/dev/null 2>&1; then
  apt_install "node and npm, to build and unit-test the Lichtblick follower extension \
(viewer/lichtblick)" nodejs npm
fi

# Debian splits venv's pip bootstrap (ensurepip) into the python3-venv package.
if [ ! -x "$venv/bin/python" ]; then
  if ! python3 -m venv "$venv" >/dev/null 2>&1; then
    rm -rf "$venv"
    apt_install "python3 -m venv needs it on Debian (the system Python refuses pip, PEP 668)" \
      python3-venv
    python3 -m venv "$venv"
  fi
fi
python="$venv/bin/python"

# `all`: every optional feature, so every test runs (see the extras in pyproject.toml).
echo "tools/test.sh: installing teleop-ui with every extra and the test tools into $venv (pip)" >&2
"$python" -m pip install -q -e '.[test,all]'
"$python" -m ruff check solver tests benchmarks tools
"$python" -m ruff format --check solver tests benchmarks tools
"$python" -m mypy
# The follower extension: `npm ci` installs exactly what viewer/lichtblick/package-lock.json pins
# (integrity-checked, no install scripts run) into viewer/lichtblick/node_modules: typescript (the
# compiler), @lichtblick/suite (the extension API's types; nothing of it runs in the app) and
# @types/node (the unit tests' types). Then the build (dist/extension.js, which
# tests/test_pack_extension_tool.py checks the repository's .foxe against) and its unit tests.
echo "tools/test.sh: installing the follower extension's build tools into \
viewer/lichtblick/node_modules (npm ci: typescript, @lichtblick/suite types, @types/node)" >&2
(
  cd viewer/lichtblick
  npm ci --ignore-scripts --no-audit --no-fund --loglevel=error
  npm run --silent build
  npm test --silent
)
# -n auto: one pytest-xdist worker per core; --dist loadfile keeps a file's tests (and its
# module fixtures: a roscore, a browser, a cached bag) in one worker.
"$python" -m pytest tests benchmarks --benchmark-disable -n auto --dist loadfile "$@"

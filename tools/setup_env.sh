#!/usr/bin/env bash
# Create or refresh the project environment (.venv) so that every command of
# the project runs the same pinned set of packages.  Idempotent and cheap when
# nothing changed: a stamp keyed by the requirement files skips the installs.
#
# Which ROS 2 launch system is used:
#   * If a real ROS 2 install is active (its `ros2` on PATH and its `launch`
#     importable, e.g. after `source /opt/ros/jazzy/setup.bash`), the venv is
#     created with --system-site-packages and uses that ROS 2: no rclpy wheels,
#     no clean-room launch.
#   * Otherwise rclpy and messages come from PyPI wheels and our clean-room
#     `launch`, `launch_ros` and `ros2` (tools/cleanroom) are installed.
#   USE_SYSTEM_ROS=1 / USE_SYSTEM_ROS=0 forces either choice.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="${TEXTBOOK_VENV:-$root/.venv}"   # the parity command makes build/jazzy/venv
python="${PYTHON:-python3}"

real_ros_present() {
  command -v ros2 >/dev/null 2>&1 && "$python" -c 'import launch, launch_ros' >/dev/null 2>&1
}

# The ros-* wheels make .venv a ROS 2 prefix (share/, lib/, include/, like
# /opt/ros/jazzy).  Two fixes let `colcon build` of an interface package
# (rosidl_generate_interfaces) use it; both idempotent, only without a real ROS,
# and both only in the wheels' CMake files (no other process sees a change):
#  1. the wheels were built with the Python in /opt/python/cp311-cp311, and
#     their exported CMake files still name its include and site-packages
#     folders: point those at this interpreter's;
#  2. ament's CMake looks up the ament index (which typesupports exist, ...)
#     only in AMENT_PREFIX_PATH, where a sourced /opt/ros/jazzy would be:
#     search .venv after it.
make_venv_a_ros_prefix() {
  local include site index_path
  include="$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["include"])')"
  site="$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
  { grep -rlZ --include='*.cmake' '/opt/python/cp311-cp311/' "$venv/share" || true; } \
    | xargs -0 -r sed -i -e "s#/opt/python/cp311-cp311/include/python3.11#$include#g" \
        -e "s#/opt/python/cp311-cp311/lib/python3.11/site-packages#$site#g"
  index_path="$venv/share/ament_cmake_core/cmake/index/ament_index_get_prefix_path.cmake"
  if [ -f "$index_path" ] && ! grep -q 'tools/setup_env.sh' "$index_path"; then
    sed -i "/^  set(\${var} \"\${prefix_path}\" PARENT_SCOPE)/i\\
  list(APPEND prefix_path \"$venv\")  # tools/setup_env.sh: .venv is a ROS 2 prefix" "$index_path"
  fi
}

# The wheels' Fast DDS can leave a node spinning for ever at shutdown (an
# overflowed "wait forever" deadline; tools/ddsfix/forever_wait.c says why).
# Build the LD_PRELOAD shim that textbook.isolation gives every ROS run, into
# the venv, only with the wheels (a real ROS 2 is built for its own glibc and
# needs none); rebuilt when its source changes, also when the rest is current.
build_ddsfix() {
  local src="$root/tools/ddsfix/forever_wait.c" lib="$venv/lib/ddsfix/libforever_wait.so"
  [ "$USE_SYSTEM_ROS" = 0 ] || return 0
  [ "$lib" -nt "$src" ] && return 0
  mkdir -p "$(dirname "$lib")"
  if "${CC:-cc}" -O2 -Wall -shared -fPIC -o "$lib.tmp" "$src" -ldl; then
    mv "$lib.tmp" "$lib"
  else
    echo "setup: could not build $lib (a C compiler?): nodes may hang at shutdown" >&2
  fi
}

# The browser test of the site (tests/site/test_browser.py) drives Debian's
# chromium through chromedriver; install them when missing and we may.
if ! command -v chromium >/dev/null 2>&1 || ! command -v chromedriver >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "setup: installing chromium and chromium-driver for the browser test" >&2
    { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
        chromium chromium-driver >/dev/null; } || echo "setup: could not install chromium" >&2
  fi
fi

if [ -z "${USE_SYSTEM_ROS:-}" ]; then
  if real_ros_present; then USE_SYSTEM_ROS=1; else USE_SYSTEM_ROS=0; fi
fi

stamp_input="$(cat "$root/requirements/lock.txt" "$root/requirements/base.in" \
  "$root/pyproject.toml" "$root/tools/cleanroom/pyproject.toml" \
  "$root/tools/rclhelpers/pyproject.toml" "$root/tools/speccheck/pyproject.toml" \
  "$root/tools/speccheck/setup.py" "$0"; echo "system_ros=$USE_SYSTEM_ROS")"
stamp="$(printf '%s' "$stamp_input" | sha256sum | cut -c1-16)"
if [ -f "$venv/.setup-stamp" ] && [ "$(cat "$venv/.setup-stamp")" = "$stamp" ]; then
  build_ddsfix
  exit 0
fi

echo "setup: creating the project environment in $venv (system ROS: $USE_SYSTEM_ROS)" >&2
# Every venv below is made with --clear: no package of an older set lingers
# (a pytest the set no longer has would shadow the system's).
reqs="$(mktemp)"
constraints="$(mktemp)"
trap 'rm -f "$reqs" "$constraints"' EXIT
cp "$root/requirements/lock.txt" "$constraints"
if [ "$USE_SYSTEM_ROS" = 1 ]; then
  "$python" -m venv --clear --system-site-packages "$venv"
  # ROS 2, CMake and (where the system has it) pytest come from the system, as
  # a ROS user has them: a lesson's `python -m pytest` and `colcon test` load
  # Jazzy's launch_testing plugin, which a newer pytest than the system's
  # (Ubuntu 24.04: 7.4.4) refuses ("Argument(s) {'path'} are declared in the
  # hookimpl but can not be found in the hookspec").  colcon is the exception
  # (below).
  drop='ros-|cmake$|colcon-'
  if "$venv/bin/python" -c 'import pytest' 2>/dev/null; then
    drop="$drop|pytest$"
    grep -v -E '^(pytest|pluggy|iniconfig)==' "$root/requirements/lock.txt" > "$constraints"
  fi
  grep -v -E "^($drop)" "$root/requirements/base.in" > "$reqs"
else
  "$python" -m venv --clear "$venv"
  cp "$root/requirements/base.in" "$reqs"
fi
pip=("$venv/bin/python" -m pip --disable-pip-version-check -q)
"${pip[@]}" install -c "$constraints" -r "$reqs"
# rclhelpers (tools/rclhelpers) first: the root and the clean room depend on
# it, and it is on no index.
"${pip[@]}" install -c "$constraints" -e "$root/tools/rclhelpers"
"${pip[@]}" install -c "$constraints" -e "$root"
# after labkit (root); --no-deps: its dependencies are installed above (base.in and
# the editable rclhelpers, which its setup.py would otherwise reinstall from a copy)
"${pip[@]}" install -c "$constraints" --no-deps -e "$root/tools/speccheck"
if [ "$USE_SYSTEM_ROS" = 0 ]; then
  "${pip[@]}" install -c "$constraints" -e "$root/tools/cleanroom"
  make_venv_a_ros_prefix
else
  # colcon itself goes into the venv too, as docs.ros.org's "Using Python
  # Packages with ROS 2" does for a venv: the system's colcon runs the system's
  # python, so `colcon test` could not import the book's tools (6.15's package
  # test imports speccheck: "collection failure").  The system's colcon is
  # visible to pip here, hence --ignore-installed; its dependencies are the
  # system's (--no-deps).
  grep -E '^colcon-' "$root/requirements/lock.txt" > "$reqs"
  "${pip[@]}" install --no-deps --ignore-installed -r "$reqs"
fi
build_ddsfix
"$venv/bin/python" -m ipykernel install --sys-prefix --name python3 >/dev/null
"$venv/bin/python" -m textbook.lab_kernel --install >/dev/null  # the book's kernel (make lab)
echo "$stamp" > "$venv/.setup-stamp"

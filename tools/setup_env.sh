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
venv="$root/.venv"
python="${PYTHON:-python3}"

real_ros_present() {
  command -v ros2 >/dev/null 2>&1 && "$python" -c 'import launch, launch_ros' >/dev/null 2>&1
}

if [ -z "${USE_SYSTEM_ROS:-}" ]; then
  if real_ros_present; then USE_SYSTEM_ROS=1; else USE_SYSTEM_ROS=0; fi
fi

stamp_input="$(cat "$root/requirements/lock.txt" "$root/requirements/base.in" \
  "$root/pyproject.toml" "$root/tools/cleanroom/pyproject.toml" "$0"; echo "system_ros=$USE_SYSTEM_ROS")"
stamp="$(printf '%s' "$stamp_input" | sha256sum | cut -c1-16)"
if [ -f "$venv/.setup-stamp" ] && [ "$(cat "$venv/.setup-stamp")" = "$stamp" ]; then
  exit 0
fi

echo "setup: creating the project environment in .venv (system ROS: $USE_SYSTEM_ROS)" >&2
reqs="$(mktemp)"
trap 'rm -f "$reqs"' EXIT
if [ "$USE_SYSTEM_ROS" = 1 ]; then
  "$python" -m venv --system-site-packages "$venv"
  grep -v -E '^ros-jazzy-' "$root/requirements/base.in" > "$reqs"
else
  "$python" -m venv "$venv"
  cp "$root/requirements/base.in" "$reqs"
fi
pip=("$venv/bin/python" -m pip --disable-pip-version-check -q)
"${pip[@]}" install -c "$root/requirements/lock.txt" -r "$reqs"
"${pip[@]}" install -c "$root/requirements/lock.txt" -e "$root"
if [ "$USE_SYSTEM_ROS" = 0 ]; then
  "${pip[@]}" install -c "$root/requirements/lock.txt" -e "$root/tools/cleanroom"
fi
"$venv/bin/python" -m ipykernel install --sys-prefix --name python3 >/dev/null
echo "$stamp" > "$venv/.setup-stamp"

#!/usr/bin/env bash
# Installs what the project needs and is missing: Debian's ROS 1 packages and build tools from apt,
# xacro from PyPI for Debian's /usr/bin/python3. Idempotent; prints nothing when all is there.
set -euo pipefail

APT_PACKAGES=(
  # build
  g++ make cmake catkin python3-catkin-pkg python3-setuptools
  # a compiler cache: a fresh clone on a machine that built before compiles only what changed
  ccache
  # catkin_tools (`catkin build`): users build their own workspaces on the install space with it too
  catkin-tools
  ros-message-generation ros-message-runtime python3-genmsg python3-genpy python3-gencpp
  # ROS 1 core: client libraries and the command-line tools the tutorial uses
  libroscpp-dev python3-rospy python3-rospkg rospack-tools rosbash
  python3-roslaunch python3-rosmaster python3-rosnode python3-rostopic python3-rosservice
  python3-rosparam ros-robot-state-publisher
  # messages: definitions (for catkin), C++ headers, Python modules
  ros-std-msgs libstd-msgs-dev python3-std-msgs
  ros-std-srvs libstd-srvs-dev python3-std-srvs
  ros-sensor-msgs libsensor-msgs-dev python3-sensor-msgs
  ros-geometry-msgs libgeometry-msgs-dev python3-geometry-msgs
  ros-nav-msgs libnav-msgs-dev python3-nav-msgs
  ros-rosgraph-msgs libros-rosgraph-msgs-dev python3-rosgraph-msgs
  ros-tf2-msgs libtf2-msgs-dev python3-tf2-msgs python3-tf2-ros
  ros-trajectory-msgs libtrajectory-msgs-dev python3-trajectory-msgs   # gazebo_msgs/SetJointTrajectory, trajectory controllers
  # dynamic_reconfigure: its messages and server (the node's /gazebo/set_parameters, gazebo_ros's
  # physics reconfigure), its Python client for scripts and the tests
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  # actions: control_msgs/FollowJointTrajectory (the node serves it with actionlib)
  ros-actionlib-msgs libactionlib-msgs-dev python3-actionlib-msgs libactionlib-dev python3-actionlib
  # the plant: physics, URDF parsing, XML, Python bindings
  libbullet-dev liburdfdom-dev liburdfdom-headers-dev liburdfdom-tools libtinyxml2-dev libtinyxml-dev
  libconsole-bridge-dev libassimp-dev nlohmann-json3-dev
  # the sensors: ray casting (Embree) and mesh textures (stb_image)
  libembree-dev libstb-dev
  # the Python module's CarBatch steps worlds side by side on TBB's threads
  libtbb-dev
  # Gazebo 11's C++ API for users' plugins (include/gazebo-11/): the libraries Gazebo itself uses,
  # sdformat for a plugin's <plugin> element and ignition-math for poses and vectors; protobuf for
  # Gazebo's messages (gazebo::msgs) on its transport
  libsdformat-dev libignition-math-dev libboost-dev libprotobuf-dev protobuf-compiler
  # the cameras' OpenGL: EGL without a display, OpenGL ES 3, Mesa's llvmpipe where there is no GPU
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  # the cameras' levels of detail: meshoptimizer's simplifier
  libmeshoptimizer-dev
  pybind11-dev python3-dev
  # rviz beside the browser viewer (rviz:=true), the world's markers for it, and a virtual screen
  # (Xvfb) with xwd for the test that screenshots it
  rviz ros-visualization-msgs python3-visualization-msgs xvfb x11-apps
  # Python for nodes and tests
  python3-numpy python3-yaml python3-pytest python3-pip python3-matplotlib
  # the suite runs on every core (pytest-xdist: make test's -n auto)
  python3-pytest-xdist
  # the racing environments' render_mode "human": a Tk window (tkinter)
  python3-tk
  # f1tenth's maps saved as PNG (racing/f1tenth_map.py reads PGM itself, the rest through Pillow)
  python3-pil
  # C++ unit tests (catkin_add_gtest builds googletest from its sources)
  googletest libgtest-dev
  # rostests (rostest, hztest) and recording simulations
  python3-rostest librostest-dev python3-rosbag
  # gdb: gazebo_ros's debug script runs gzserver under it (test_world_launch_files.py runs it)
  gdb
)
# The browser viewer: its server (aiohttp), and headless chromium driven by selenium for its tests.
APT_PACKAGES+=(python3-aiohttp chromium chromium-driver python3-selenium)
# npm bundles the viewer's page at build time (three.js, esbuild); Debian's nodejs and npm where
# there is no node at all (a machine with another node keeps it).
command -v npm >/dev/null || APT_PACKAGES+=(nodejs npm)
# xacro from PyPI (Debian has no xacro); compat/xacro runs it with rospack's $(find).
PIP_PACKAGES=(xacro==2.1.1)
# Racing for learning (tianracer_description.racing, .sweep): Gymnasium, PettingZoo, Ray for sweeps,
# stable-baselines3 for the PPO example with PyTorch's CPU build; pandas below 3 (3 needs numpy 2).
PIP_PACKAGES+=(gymnasium==1.4.0 pettingzoo==1.27.0 ray==2.60.0 stable-baselines3==2.9.2 pandas==2.3.3 tqdm==4.70.1)
# Videos of episodes: Gymnasium's RecordVideo writes them with MoviePy (its imageio-ffmpeg brings ffmpeg);
# 1.0.3, as MoviePy 2 needs numpy 1.25 and Debian's is 1.24.
PIP_PACKAGES+=(moviepy==1.0.3)
# PyTorch's CPU build where pip finds it (a wheel of a local find-links, as on the project's
# machines); else PyPI's, whose default build carries CUDA (several GB) and runs on the CPU as well.
# An installed 2.13.0 of either build is taken as it is (the check below compares the version's start).
TORCH=torch==2.13.0
PY=/usr/bin/python3
SUDO=
[ "$(id -u)" -eq 0 ] || SUDO=sudo

# One dpkg-query for every package: a package it does not know at all is missing too.
missing=()
declare -A installed_apt=()
while read -r name status; do
  [ "${status:0:2}" = "ii" ] && installed_apt[${name%%:*}]=1
done < <(dpkg-query -W -f='${Package} ${db:Status-Abbrev}\n' "${APT_PACKAGES[@]}" 2>/dev/null || true)
for pkg in "${APT_PACKAGES[@]}"; do
  [ -n "${installed_apt[$pkg]:-}" ] || missing+=("$pkg")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing from apt: ${missing[*]}"
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# One interpreter asks importlib.metadata for every requirement: those not installed at that version.
mapfile -t missing < <($PY - "${PIP_PACKAGES[@]}" "$TORCH" <<'PYTHON'
import importlib.metadata as metadata
import sys
for requirement in sys.argv[1:]:
    name, _, version = requirement.partition('==')
    try:
        installed = metadata.version(name)
    except metadata.PackageNotFoundError:
        installed = None
    # torch: 2.13.0 of any build (2.13.0+cpu is PyTorch's CPU build of it)
    if installed != version and not (name == 'torch' and installed and installed.split('+')[0] == version):
        print(requirement)
PYTHON
)
if [ ${#missing[@]} -gt 0 ]; then
  # torch: the CPU build where pip finds one (its dry run resolves without downloading the wheel)
  for i in "${!missing[@]}"; do
    if [ "${missing[$i]}" = "$TORCH" ] && \
       $PY -m pip install -q --dry-run --no-deps --break-system-packages "$TORCH+cpu" >/dev/null 2>&1; then
      missing[$i]="$TORCH+cpu"
    fi
  done
  echo "setup: installing from PyPI for $PY: ${missing[*]}"
  # Debian marks its Python as externally managed; these go to /usr/local, beside nothing of Debian's.
  # Debian's numpy stays: its scipy and matplotlib are built for it, and a numpy in /usr/local would
  # shadow it.
  constraints=$(mktemp)
  $PY -c 'import numpy; print("numpy==" + numpy.__version__)' > "$constraints"
  $SUDO $PY -m pip install -q --root-user-action=ignore --break-system-packages -c "$constraints" "${missing[@]}"
  rm -f "$constraints"
fi

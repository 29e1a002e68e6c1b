#!/usr/bin/env bash
# `make sim`: starts the simulation. Until the plant node and launch files exist, it checks the
# car's model and says what is still to come.
set -euo pipefail
urdf=$(mktemp --suffix=.urdf)
trap 'rm -f "$urdf"' EXIT
"$(rospack find xacro)/xacro" --inorder "$(rospack find tianracer_description)/urdf/tianracer_description.xacro" > "$urdf"
check_urdf "$urdf"
cat <<'MSG'

The car's model builds and parses. Not built yet: the Bullet plant (launch/empty_world.launch),
the tutorial's launch files (launch/tianracer.launch, launch/control.launch) and the
controller_manager scripts; `make sim` will start `roslaunch tianracer_description
tianracer.launch` once they exist.
MSG

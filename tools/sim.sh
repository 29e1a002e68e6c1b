#!/usr/bin/env bash
# `make sim`: the tutorial's tianracer.launch, headless, with a note on how to drive.
set -euo pipefail
cat <<MSG
Starting the Tianracer simulation (roslaunch tianracer_description tianracer.launch gui:=false).
In another terminal:
    cd '$(pwd)'; source .ws/devel/setup.bash; export ROS_IP=127.0.0.1
    rostopic pub /tianracer/cmd_vel -r 10 geometry_msgs/Twist "{linear: {x: 1.0}, angular: {z: 1.0}}"
    rosservice call /tianracer/controller_manager/list_controllers
Ctrl-C here stops it.
MSG
exec roslaunch tianracer_description tianracer.launch gui:=false headless:=true "$@"

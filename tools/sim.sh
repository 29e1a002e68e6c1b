#!/usr/bin/env bash
# `make sim`: the tutorial's tianracer.launch as the tutorial starts it, with the browser viewer in
# gzclient's place (gui:=true, the launch file's default), the address to open printed first, before
# roslaunch's logs bury it. `make sim GUI=false` runs it headless, as a server.
set -euo pipefail
gui=${GUI:-true}
case "$gui" in
  true | false) ;;
  *) echo "make sim: GUI=$gui: say GUI=true (the viewer, the default) or GUI=false (headless)" >&2; exit 2 ;;
esac
# empty_world.launch's viewer_port default; tianracer.launch is the tutorial's, byte for byte, and
# passes no port of its own.
viewer_url=http://127.0.0.1:8080/
if [ "$gui" = true ]; then
  cat <<MSG
The world in a browser: open $viewer_url
  (from another machine: ssh -L 8080:localhost:8080 $(hostname) first; GUI=false starts it headless)
MSG
fi
cat <<MSG
Starting the Tianracer simulation (roslaunch tianracer_description tianracer.launch gui:=$gui).
In another terminal:
    cd '$(pwd)'; source .ws/devel/setup.bash; export ROS_IP=127.0.0.1
    rostopic pub /tianracer/cmd_vel -r 10 geometry_msgs/Twist "{linear: {x: 1.0}, angular: {z: 1.0}}"
    rosservice call /tianracer/controller_manager/list_controllers
Ctrl-C here stops it.
MSG
exec roslaunch tianracer_description tianracer.launch gui:="$gui" headless:="$([ "$gui" = true ] && echo false || echo true)" "$@"

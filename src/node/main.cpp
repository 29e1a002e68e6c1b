// bullet_plant: the simulator node that stands in for gzserver + gazebo_ros + gazebo_ros_control.
#include <cstdio>

#include <ros/ros.h>

#include "ros_plant.h"

int main(int argc, char** argv)
{
  // One line at a time even into a log file or a pipe, so the status and errors show when they happen.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  ros::init(argc, argv, "bullet_plant");
  ros::NodeHandle nh, private_nh("~");
  try
  {
    bullet_plant::RosPlant plant(nh, private_nh);
    ros::AsyncSpinner spinner(2);  // services wait on the simulation thread; keep callbacks flowing
    spinner.start();
    plant.run();
    spinner.stop();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL("bullet_plant: %s", e.what());
    return 1;
  }
  return 0;
}

// bullet_plant: the simulator node that stands in for gzserver + gazebo_ros + gazebo_ros_control.
#include <cstdio>
#include <cstring>

#include <ros/ros.h>

#include "gazebo_ros_api_plugin.h"
#include "robot_interface.h"
#include "ros_plant.h"

int main(int argc, char** argv)
{
  // One line at a time even into a log file or a pipe, so the status and errors show when they happen.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      std::printf(
          "usage: bullet_plant [__name:=NAME (default gazebo)] [_param:=value ...]\n"
          "The Bullet simulator node standing in for gzserver + gazebo_ros + gazebo_ros_control.\n"
          "Private parameters:\n"
          "  ~world_name           world file (SDF) to load, as a path or as Gazebo finds it (worlds/empty.world);\n"
          "                        empty for an empty world\n"
          "  ~real_time_factor     simulated seconds per wall second (>= 0.001; 0 or less: as fast as possible);\n"
          "                        default: the world's <real_time_update_rate> x <max_step_size>, as Gazebo paces\n"
          "  ~pub_clock_frequency  /clock rate in Hz (default 100)\n"
          "  ~paused               start paused (default false)\n"
          "  ~iterations           simulate this many steps, then stop (default 0: until shut down)\n"
          "  ~publishing_threads   threads that publish what each step built (default 1; 0: the simulation\n"
          "                        thread publishes); the simulation is the same with any number\n"
          "  ~enable_ros_network   false: none of gazebo_ros's services and topics, as Gazebo (default true)\n"
          "  ~system_plugins       Gazebo system plugin files of the user's own to load (gzserver -s FILE): a list,\n"
          "                        or one file a line\n"
          "  ~server_arguments     the command line their Load gets, as ~system_plugins (default gzserver)\n"
          "  ~verbose              Gazebo's console writes what plugins say (gzmsg), as gzserver --verbose\n"
          "Services and topics: gazebo_ros's (~spawn_urdf_model, ~get_model_state, ~model_states, ...; docs/gazebo_compatibility.md)\n");
      return 0;
    }
  ros::init(argc, argv, "gazebo");  // gazebo_ros's node name: its services are /gazebo/...
  ros::NodeHandle nh, private_nh("~");
  try
  {
    // gzserver's shape: the world, each model's plugins loaded as it spawns, gazebo_ros's system plugin.
    bullet_plant::RosPlant plant(nh, private_nh, [](bullet_plant::RosPlant& p, bullet_plant::Robot& robot) {
      return std::unique_ptr<bullet_plant::ModelPlugins>(new bullet_plant::RobotInterface(p, robot));
    });
    bullet_plant::GazeboRosApiPlugin gazebo_ros_api(plant, private_nh);
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

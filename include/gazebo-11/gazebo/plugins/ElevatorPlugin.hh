// Gazebo 11's ElevatorPlugin (libElevatorPlugin.so), a model plugin of Gazebo's own that
// gazebo_ros_pkgs' gazebo_ros_elevator derives from: an elevator car on a lift joint and a door
// joint. A floor (a number in a GzString on the plugin's <topic>, "~/elevator" by default, or
// MoveToFloor) closes the door, moves the car to floor x <floor_height>, opens the door, holds it
// open <door_wait_time> seconds and closes it. Both joints are driven by force through PIDs, as
// Gazebo's. A command while the elevator is busy is ignored.
#pragma once

#include <memory>

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/common/UpdateInfo.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class ElevatorPluginPrivate;

class GAZEBO_VISIBLE ElevatorPlugin : public ModelPlugin
{
public:
  ElevatorPlugin();
  ~ElevatorPlugin() override;
  void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf) override;
  void Reset() override;
  // Close the door, go to the floor, open the door, wait, close it; ignored while busy.
  void MoveToFloor(const int _floor);

private:
  void Update(const common::UpdateInfo& _info);
  void OnElevator(ConstGzStringPtr& _msg);
  std::unique_ptr<ElevatorPluginPrivate> dataPtr;
};
}  // namespace gazebo

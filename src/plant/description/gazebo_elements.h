// The Gazebo elements URDF's <gazebo> extensions and SDF models share: a link's <sensor>s (with their
// sensor plugins) and a model's <plugin>s. What Gazebo reads from `<gazebo reference="L"><sensor>`
// is what it reads from an SDF `<link name="L"><sensor>`. Private to the plant.
#pragma once

#include <string>

#include "description/sdf_elements.h"

#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
// The <sensor>s among `parent`'s children, of link `link` (of joint `joint`, `link` its child, where
// `parent` is a <joint>), into out.sensors; a sensor plugin the plant does not simulate is warned
// about, one refused on its sensor is an error (out.errors).
void readSensors(const sdf::ElementPtr& parent, const std::string& link, RobotDescription& out,
                 const std::string& joint = "");

// One model-level <plugin>: gazebo_ros_control, a model plugin following a link (gazebo_ros_imu,
// gazebo_ros_p3d: out.sensors), one acting on the physics (out.model_plugins); any other file is
// warned about and ignored. Its link names must already be in out.model.
void readModelPlugin(const sdf::ElementPtr& plugin, RobotDescription& out);

}  // namespace bullet_plant

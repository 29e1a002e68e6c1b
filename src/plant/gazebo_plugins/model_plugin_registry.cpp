// The model plugins this plant simulates, by kind (robot_description.cpp's pluginKind names their
// files). A new one is its own file here and a line in each of the two.
#include "bullet_plant/model_plugin.h"

namespace bullet_plant
{
std::unique_ptr<ModelPlugin> makeGazeboRosDiffDrive();
std::unique_ptr<ModelPlugin> makeGazeboRosSkidSteerDrive();
std::unique_ptr<ModelPlugin> makeGazeboRosTricycleDrive();
std::unique_ptr<ModelPlugin> makeGazeboRosPlanarMove();
std::unique_ptr<ModelPlugin> makeGazeboRosJointStatePublisher();
std::unique_ptr<ModelPlugin> makeMimicJointPlugin();
std::unique_ptr<ModelPlugin> makeHectorGazeboRosGps();
std::unique_ptr<ModelPlugin> makeHectorGazeboRosImu();
std::unique_ptr<ModelPlugin> makeHectorGazeboRosMagnetic();
std::unique_ptr<ModelPlugin> makeGazeboRosForceBasedMove();
std::unique_ptr<ModelPlugin> makeGazeboRosForce();
std::unique_ptr<ModelPlugin> makeGazeboRosF3d();
std::unique_ptr<ModelPlugin> makeGazeboRosFtSensor();
std::unique_ptr<ModelPlugin> makeGazeboRosJointPoseTrajectory();
std::unique_ptr<ModelPlugin> makeGazeboRosHandOfGod();

std::unique_ptr<ModelPlugin> createModelPlugin(PluginKind kind)
{
  switch (kind)
  {
    case PluginKind::DiffDrive: return makeGazeboRosDiffDrive();
    case PluginKind::SkidSteerDrive: return makeGazeboRosSkidSteerDrive();
    case PluginKind::TricycleDrive: return makeGazeboRosTricycleDrive();
    case PluginKind::PlanarMove: return makeGazeboRosPlanarMove();
    case PluginKind::JointStatePublisher: return makeGazeboRosJointStatePublisher();
    case PluginKind::MimicJoint: return makeMimicJointPlugin();
    case PluginKind::HectorGps: return makeHectorGazeboRosGps();
    case PluginKind::HectorImu: return makeHectorGazeboRosImu();
    case PluginKind::HectorMagnetic: return makeHectorGazeboRosMagnetic();
    case PluginKind::ForceBasedMove: return makeGazeboRosForceBasedMove();
    case PluginKind::Force: return makeGazeboRosForce();
    case PluginKind::F3d: return makeGazeboRosF3d();
    case PluginKind::FtSensor: return makeGazeboRosFtSensor();
    case PluginKind::JointPoseTrajectory: return makeGazeboRosJointPoseTrajectory();
    case PluginKind::HandOfGod: return makeGazeboRosHandOfGod();
    default: return nullptr;
  }
}

}  // namespace bullet_plant

// An SDF world as the plant reads it: <physics>, <gravity>, its <light>s, <scene>; static
// models (box/cylinder/sphere/plane/mesh collisions, nested models, <include>d models found by
// model://, resource_uri.h) as models that never move, their shapes in the world's static scene;
// every other model as a model the world simulates (sdf_model.h). The plant's own ground_plane and sun stand in for Gazebo's models of those
// names.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/geometry.h"
#include "bullet_plant/sdf_model.h"

namespace bullet_plant
{
struct StaticCollision
{
  std::string name;   // model::link::collision, as Gazebo names them
  std::string model;  // the static model it belongs to (StaticModelDescription::name)
  Shape shape;
  urdf::Pose pose;    // in the world
  double mu = 1.0;    // Gazebo's default friction
  // <surface><bounce>: restitution_coefficient, and the speed (m/s) it applies above (SDF's defaults)
  double restitution = 0.0, restitution_threshold = 100000.0;
  SurfaceDescription surface;  // the whole <surface>: mu2, fdir1 and <contact> besides
};

// What cameras (and gpu_ray lidars) see of a static model: one of its links' <visual>s.
struct StaticVisual
{
  std::string name;   // model::link::visual
  std::string model;  // the static model it belongs to
  Shape shape;
  urdf::Pose pose;    // in the world
  VisualMaterial material;  // its <material> and <transparency>
};

// A model of the world that never moves (<static>, the ground plane, a building): a model as Gazebo
// has it (gazebo_ros lists it, deletes it, teleports it), whose collisions and visuals are the
// world's static ones (StaticCollision::model, StaticVisual::model names it).
struct StaticModelDescription
{
  struct Link
  {
    std::string name;  // in the model, nested models' scoped ("inner::link")
    urdf::Pose pose;   // in the world
  };
  std::string name;
  urdf::Pose pose;     // its model frame in the world
  std::vector<Link> links;
};

// A <light> as Gazebo's renderer (OGRE) lights cameras with it (pinhole.h's Lighting): a
// directional light's diffuse and specular colours from `direction` everywhere; a point light's from
// `position`, times 1 / (constant + linear d + quadratic d^2) within `range` metres (Gazebo clamps
// constant and linear to [0, 1], rendering/Light.cc); a spot light's also times its cone's factor.
// SDF's defaults.
struct LightDescription
{
  enum class Kind { Directional, Point, Spot };
  std::string name;
  Kind kind = Kind::Point;
  urdf::Vector3 position{0, 0, 0};    // in the world
  urdf::Vector3 direction{0, 0, -1};  // the way it shines, in the world (unit): directional and spot
  Rgba diffuse{1.0f, 1.0f, 1.0f, 1.0f};
  Rgba specular{0.1f, 0.1f, 0.1f, 1.0f};
  double range = 10.0, constant = 1.0, linear = 1.0, quadratic = 0.0;  // <attenuation>
  double inner_angle = 0.0, outer_angle = 0.0, falloff = 0.0;          // <spot>: rad, full cone angles
  bool cast_shadows = false;  // only a directional light's are drawn, as in Gazebo
  bool lights() const { return kind == Kind::Directional || range > 0; }  // false: left dark (warned)
};

// The physics step's range: below a nanosecond the step rounds to zero simulated nanoseconds and
// time never advances; beyond 0.1 s nothing the plant simulates stays stable.
constexpr double kMinStepSize = 1e-9, kMaxStepSize = 0.1;  // s
// The most solver passes a step the plant takes from <iters> (ODE's quick step default: 50).
constexpr int kMaxSolverIterations = 1000;

// A <plugin> of the world: a Gazebo WorldPlugin library of the user's own, its file found on the
// plugin paths (findGazeboPluginLibrary), loaded as Gazebo loads it (gazebo_host.h).
struct WorldPluginDescription
{
  std::string name, filename, library;
  // The <plugin> element as sdformat read it, for its Load, and the root of the world's document,
  // which keeps its ancestors for its GetParent().
  ::sdf::ElementPtr element, document;
};

struct WorldDescription
{
  std::string name = "default";
  double max_step_size = 0.001;      // s, within [kMinStepSize, kMaxStepSize]
  double real_time_factor = 1.0;
  // <physics><real_time_update_rate>: the steps per wall second Gazebo's loop paces itself to (0: as
  // fast as it can). Gazebo paces by it, not by <real_time_factor>: the pace is their product's.
  double real_time_update_rate = 1000.0;
  double pace() const { return real_time_update_rate > 0 ? real_time_update_rate * max_step_size : 0.0; }
  // <physics><ode><constraints><contact_max_correcting_vel>: the fastest a contact corrects a
  // penetration, m/s (Gazebo's default).
  double contact_max_correcting_vel = 100.0;
  // <physics><ode> settings the plant's solver (Bullet's sequential impulses, iterated as ODE's quick
  // step) has an equivalent of, where the world gives them; otherwise the plant's own (10 passes,
  // no over-relaxation, no penetration allowed): <solver><iters> (1 .. kMaxSolverIterations),
  // <solver><sor> (over-relaxation of the contacts' rows, (0, 2)), <constraints><contact_surface_layer>
  // (the depth contacts leave, m).
  int solver_iterations = 0;             // 0: not given
  double sor = 0.0;                      // 0: not given
  double contact_surface_layer = -1.0;   // < 0: not given
  urdf::Vector3 gravity{0, 0, -9.8};
  // <magnetic_field> (tesla, world frame): SDF's default, Gazebo's for its magnetometer sensors.
  urdf::Vector3 magnetic_field{5.5645e-6, 22.8758e-6, -42.3884e-6};
  // <spherical_coordinates>: where the world's origin is on the earth (WGS84) and the heading of its
  // x axis, for Gazebo's GPS sensors (SDF's defaults: all 0).
  struct SphericalCoordinates
  {
    double latitude_deg = 0.0, longitude_deg = 0.0, elevation = 0.0, heading_deg = 0.0;
  } spherical_coordinates;
  // <scene>: what cameras see where nothing is hit, and the ambient light (SDF's default 0.4 grey).
  Rgba background{0.70f, 0.80f, 0.95f, 1.0f};
  Rgba ambient{0.4f, 0.4f, 0.4f, 1.0f};
  bool shadows = true;  // <scene><shadows>: a directional light's shadows in camera images (SDF's default)
  // The world's lights as its file gives them, in file order (an <include>d model://sun among them);
  // a world without any is lit by its ambient light alone.
  std::vector<LightDescription> lights;
  // The static models in file order, and their collisions and visuals.
  std::vector<StaticModelDescription> static_models;
  std::vector<StaticCollision> collisions;
  std::vector<StaticVisual> visuals;
  // The models that move (SDF's default; not <static>), in file order: the world spawns each as
  // spawn_model would, under its name and at its pose.
  std::vector<ModelDescription> models;
  // The world's plugins whose files were found, in file order; one not found is a warning.
  std::vector<WorldPluginDescription> plugins;
  std::vector<std::string> warnings;  // each unsupported element once: what, where, left out
  std::vector<std::string> errors;    // models refused (what sdf_model.h refuses), the world goes on without them
  std::string file;      // the world file; "" when parsed from text
  std::string base_dir;  // relative URIs of the world itself resolve against it ("": working directory)
};

// Parses SDF text (<sdf><world>...). Throws DescriptionError for XML that is not well-formed (with
// the line) and for values that are not numbers; elements the plant does not support are left out
// with a warning. The world has the ground its file gives it (model://ground_plane, a <plane>, a
// floor mesh) and none other, as in Gazebo.
WorldDescription parseWorldDescription(const std::string& sdf_xml, const std::string& base_dir = "");
// Reads and parses a world file; its relative URIs resolve against its directory. A name that is not
// a file is looked for as Gazebo looks for `worlds/empty.world`: in GAZEBO_RESOURCE_PATH, then in
// the gazebo_media_path exports of the packages on ROS_PACKAGE_PATH (WorldFileNotFound names them).
WorldDescription parseWorldFile(const std::string& name);
// A world file found nowhere: Gazebo's server then says so and runs worlds/empty.world (the node does).
class WorldFileNotFound : public DescriptionError
{
public:
  using DescriptionError::DescriptionError;
};
// The empty world, as Gazebo's worlds/empty.world: default physics, its sun and a ground plane.
WorldDescription emptyWorldDescription();

// What spawn_urdf_model and spawn_sdf_model are given, as gazebo_ros takes it: URDF (<robot>), an SDF
// model (<sdf><model>), or gazebo_ros's model database request (<sdf><world><include><uri>model://NAME,
// what spawn_model -database sends), found in GAZEBO_MODEL_PATH and the packages' gazebo_model_path
// exports as the world file's includes are; the include's <pose> (none: the identity, as gazebo_ros
// writes one) is the model's pose. Throws DescriptionError naming what is wrong.
ModelDescription readSpawnedModel(const std::string& model_xml);
// What Gazebo's factory is given (World::InsertModelString / InsertModelFile / InsertModelSDF): the
// same, but an <include> without a <pose> puts the model where its own <pose> says, as Gazebo's
// factory reads the model's file.
ModelDescription readInsertedModel(const std::string& model_xml);

}  // namespace bullet_plant

// A model as the plant simulates it, read from URDF as gazebo_ros reads one: urdfdom's kinematic tree
// plus the Gazebo extensions (<gazebo reference> surface tags and sensors, the gazebo_ros_control
// plugin block) and the <transmission> elements that gazebo_ros_control turns into joint handles. An
// SDF model becomes the same (sdf_model.h).
#pragma once

#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <sdf/Element.hh>
#include <urdf_model/model.h>
#include <urdf_world/types.h>

#include "bullet_plant/geometry.h"

namespace bullet_plant
{
// Thrown for input that cannot describe a robot or world; the message names the offending thing.
class DescriptionError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct Noise
{
  bool gaussian = false;
  double mean = 0.0;
  double stddev = 0.0;
};

// A camera's <distortion> (SDF 1.5+): Brown's radial k1 k2 k3 and tangential p1 p2 about <center>,
// a point of the image in 0..1 (SDF's defaults: 0 and 0.5 0.5).
struct CameraDistortion
{
  bool given = false;  // the <camera> has a <distortion>
  double k1 = 0, k2 = 0, k3 = 0, p1 = 0, p2 = 0;
  double center_x = 0.5, center_y = 0.5;
};

struct SensorDescription;

// What the description makes of a gazebo_ros plugin file. Every file the plant simulates registers
// one under its file names (registry.h), beside the code that simulates it: a model plugin in its own
// file (GAZEBO_ROS_MODEL_PLUGIN, model_plugin.h); a sensor plugin's ROS-free half in its own file of
// src/plant/gazebo_plugins/ (GAZEBO_ROS_SENSOR_PLUGIN_FILE), its ROS half in src/node/sensor_plugins/. A
// file nobody registered is warned about at parse and ignored.
enum class PluginRole
{
  Sensor,      // inside a <sensor>: the plant builds the sensor from its type, the node's plugin publishes it
  LinkSensor,  // a model plugin following one link (<bodyName>) described as a sensor: gazebo_ros_imu, gazebo_ros_p3d
  Model,       // a model plugin that acts on the physics (model_plugin.h), from <gazebo><plugin>
};

// Whose naming rules (plugin_names.h) a plugin follows where its sensor's type alone does not say.
enum class PluginNaming
{
  Default,         // its sensor type's (laser, camera, imu, p3d, bumper); a model plugin: "" is the global namespace
  Range,           // ray sensors whose plugins name their topics and frames their own way
  Velodyne,
  BlockLaser,
  HectorSonar,
  MultiCamera,     // topics under <cameraName>/left and /right
  GazeboRos,       // model plugins on gazebo_ros's GazeboRos helper: an empty namespace is the model's name, the namespace the tf prefix
  ModelNamespace,  // an empty namespace is the model's name, no tf prefix (joint_state_publisher)
};

struct PluginFile
{
  PluginRole role = PluginRole::Model;
  PluginNaming naming = PluginNaming::Default;
  // LinkSensor: the sensor type it is described as ("imu", "p3d").
  std::string sensor_type;
  // Sensor: why it cannot load on this <sensor> in upstream's words ("needs a <sensor type=...>"),
  // "" when it can; a refused plugin publishes nothing. Null: it loads on any.
  std::string (*refusal)(const SensorDescription& sensor) = nullptr;
  // Model: the element naming where it reads pid gains from the parameter server (the mimic joint
  // plugin's <hasPID>), for the node to copy them there; "" for none.
  std::string pid_gains_element;
};

// The registered facts of `filename` (libgazebo_ros_*.so); null for a file the plant does not simulate.
const PluginFile* findPluginFile(const std::string& filename);
// Where Gazebo would load the plugin library `filename` from: an absolute path that exists, else
// the first folder of GAZEBO_PLUGIN_PATH, then of LD_LIBRARY_PATH (where catkin puts the
// workspaces' lib folders), that holds it; "" where none does.
std::string findGazeboPluginLibrary(const std::string& filename);
// The files registered, for messages ("gazebo_ros_control, gazebo_ros_laser, ...").
std::string simulatedPluginNames();

// A <gazebo><plugin> block of a model plugin that acts on the physics (model_plugin.h): its
// parameters, read by the plugin's Load with upstream's names and defaults.
struct ModelPluginDescription
{
  std::string name, filename;  // filename: a registered model plugin's (findPluginFile)
  std::map<std::string, std::string> params;  // child element -> its text
  // A Gazebo plugin library of the user's own: the file `filename` found on the plugin paths
  // (findGazeboPluginLibrary), loaded as Gazebo loads it (src/plant/gazebo_host/); "" for the
  // plant's own plugin of that name.
  std::string library;
  // The <plugin> element as sdformat read it, for its Load, and the root of the document it is in,
  // which keeps its ancestors (its model, the world) for its GetParent().
  ::sdf::ElementPtr element, document;

  bool has(const std::string& key) const { return params.count(key) > 0; }
  std::string text(const std::string& key, const std::string& fallback) const;
  // Throw DescriptionError naming the plugin and the element when the text is not a number or a
  // boolean (sdf's true/false/1/0).
  double number(const std::string& key, double fallback) const;
  bool flag(const std::string& key, bool fallback) const;
  // "x y z", or one number for all three (hector's error models take either).
  urdf::Vector3 vector(const std::string& key, const urdf::Vector3& fallback) const;
};

// One <sensor> inside <gazebo reference="LINK">, with the plugin parameters gazebo_ros reads; the
// model plugins gazebo_ros_imu and gazebo_ros_p3d are described the same way (type "imu" or
// "p3d", link = their bodyName).
struct SensorDescription
{
  std::string name;
  std::string type;  // "ray", "gpu_ray", "camera", "depth", "imu", "p3d", "contact"
  std::string link;
  urdf::Pose pose;   // in the link frame (<pose>); in the joint's frame for a joint's sensor
  // A sensor in a <joint> (force_torque: SDF's, or a URDF's <gazebo reference="JOINT">): its joint,
  // `link` being the joint's child link; "" for a link's sensor.
  std::string joint;
  // A <sensor type="multicamera"> is one "camera" description per <camera>, named
  // "<sensor>::<camera>", its pose the sensor's composed with the camera's: this is the <camera>'s
  // name ("left"); empty for every other sensor.
  std::string multicamera_camera;
  double update_rate = 0.0;  // Hz; 0 = every physics step
  // ray
  int horizontal_samples = 1;
  double horizontal_min_angle = 0.0, horizontal_max_angle = 0.0;
  int vertical_samples = 1;
  double vertical_min_angle = 0.0, vertical_max_angle = 0.0;
  double range_min = 0.0, range_max = 0.0, range_resolution = 0.0;  // a sonar's <min> and <max> too
  // sonar: its <radius> and <geometry> ("cone" or "sphere")
  double sonar_radius = 0.0;
  std::string sonar_geometry;
  // camera and depth
  double horizontal_fov = 0.0;
  int image_width = 0, image_height = 0;
  std::string image_format;
  double clip_near = 0.1, clip_far = 100.0;  // SDF's (camera.sdf) where a <camera> has no <clip>
  CameraDistortion distortion;
  // What was wrong in its elements and what the plant took instead, for one warning each at spawn.
  std::vector<std::string> description_problems;
  // contact: the <contact><collision> names, SDF collisions of the sensor's link (after lumping)
  std::vector<std::string> contact_collisions;
  Noise noise;
  // the plugin block: filename and its child elements as text (topicName, frameName, cameraName, ...)
  bool plugin_given = false;  // it has a <plugin> block
  std::string plugin_name, plugin_filename;
  std::map<std::string, std::string> plugin;
  // The registered file simulating its plugin; null for a sensor without a <plugin>, with a file the
  // plant does not simulate as a sensor plugin (warned about), or with one refused (an error): then
  // it publishes nothing on ROS.
  const PluginFile* plugin_file = nullptr;
  // A Gazebo sensor plugin library of the user's own: the file plugin_filename found on the plugin
  // paths (findGazeboPluginLibrary), loaded as Gazebo loads it over Gazebo's sensor of this one
  // (GazeboHost::loadSensorPlugin); plugin_file is then null. "" otherwise. With it, the <sensor> and
  // <plugin> elements as sdformat read them and their document's root, which keeps their ancestors.
  std::string library;
  ::sdf::ElementPtr element, plugin_element, document;
  bool model_plugin = false;  // from <gazebo><plugin>, not from a <sensor>
  std::string pluginParam(const std::string& key, const std::string& fallback = "") const;
  bool hasPluginParam(const std::string& key) const { return plugin.count(key) > 0; }
  // A number from the plugin block, or fallback when absent; throws DescriptionError naming the
  // sensor and the element when the text is not a number.
  double pluginNumber(const std::string& key, double fallback) const;
  // The plugin block with a model plugin's typed readers (hector's sensor plugins share them).
  ModelPluginDescription pluginBlock() const
  {
    ModelPluginDescription block;
    block.name = plugin_name;
    block.filename = plugin_filename;
    block.params = plugin;
    return block;
  }
};

// A collision's <surface> (SDF), or a link's <gazebo reference> friction tags (URDF: `urdf`).
struct SurfaceDescription
{
  // <friction><ode>: mu along fdir1 (or ODE's default first direction), mu2 across it.
  double mu1 = 1.0, mu2 = 1.0;  // Gazebo's defaults
  urdf::Vector3 fdir1{0, 0, 0};  // in the collision's frame; zero: not given (SDF's default)
  // ODE's force-dependent slip (m/s per N of friction) along fdir1 and across it; SDF's 0: none.
  double slip1 = 0.0, slip2 = 0.0;
  // <contact><ode>: negative where not given (the plant's own rigid contact then, see docs/sdf.md).
  double kp = -1.0, kd = -1.0;
  double max_vel = -1.0, min_depth = -1.0;
  // SDF's <bounce>: the share of the normal speed a contact gives back, above `threshold` m/s.
  double restitution = 0.0, restitution_threshold = 100000.0;
  bool given = false;
  // From a URDF's <gazebo reference> tags: the plant takes min(mu1, mu2) for the link and leaves
  // kp and kd out (the tutorial car's wheels declare them; its contacts stay the plant's own).
  bool urdf = false;
};

// SDF's <joint><axis><dynamics> spring: a torque (force) -stiffness * (q - reference) on the joint.
struct JointSpring
{
  double stiffness = 0.0, reference = 0.0;
};

// A shape URDF has no element for (SDF's capsule and ellipsoid) in the URDF tree: a urdf::Mesh
// without a file, which code that knows only URDF's shapes finds nothing in, carrying the shape.
struct ShapeGeometry : urdf::Mesh
{
  Shape shape;
};

// SDF's per-link physics that URDF cannot say, with SDF's defaults.
struct LinkPhysics
{
  bool gravity = true;        // <gravity>: false, the link feels no gravity
  bool kinematic = false;     // <kinematic>: moved only by the states and velocities set, not by dynamics
  bool self_collide = false;  // <self_collide>, else its model's: collides with the model's other links
};

// Two movable (URDF) joints whose positions are tied, q_follower = multiplier * q_leader: an SDF
// screw's turn (leader) and the slide the plant adds for it (follower), a gearbox's two gears.
struct JointCouplingDescription
{
  std::string name;              // the SDF joint (screw or gearbox), for messages
  std::string leader, follower;  // URDF joints
  double multiplier = 0.0;
  bool follower_internal = false;  // the plant's own joint (a screw's slide): no joint of the robot's own
};

struct TransmissionDescription
{
  std::string name;
  std::string joint;
  std::string hardware_interface;  // normalised to "hardware_interface/XJointInterface"
};

// The <gazebo><plugin filename="libgazebo_ros_control.so"> block.
struct ControlPluginDescription
{
  bool present = false;
  std::string robot_namespace;    // empty: use the spawn namespace
  std::string robot_param = "robot_description";
  double control_period = 0.0;    // s; 0: the physics step
  std::string e_stop_topic;
  // legacyModeNS (default true, as gazebo_ros_control): pid_gains at /gazebo_ros_control/pid_gains
  // in Gazebo; the plant reads them under the robot namespace either way (docs/interfaces.md section 11).
  bool legacy_mode_ns = true;
  bool legacy_mode_ns_given = false;
  std::string sim_type = "gazebo_ros_control/DefaultRobotHWSim";  // robotSimType

  // The robot's control namespace, normalised ("/tianracer"): <robotNamespace>, else the spawn
  // namespace. Its controller manager, pid_gains and controller topics live there.
  std::string controlNamespace(const std::string& spawn_namespace) const;
  // The same as written, before normalising: what name checks and their errors quote.
  std::string givenControlNamespace(const std::string& spawn_namespace) const
  {
    return robot_namespace.empty() ? spawn_namespace : robot_namespace;
  }
};

struct RobotDescription
{
  urdf::ModelInterfaceSharedPtr model;
  bool is_static = false;  // <gazebo><static>true</static></gazebo>: the whole robot never moves
  // Joints whose wrench is measured from the start (URDF's <gazebo reference="JOINT">
  // <provideFeedback>true</provideFeedback>, SDF's <physics><provide_feedback>): Joint::GetForceTorque
  // answers from the first call, as Gazebo's ODE does for them.
  std::set<std::string> joint_feedback;
  ControlPluginDescription control;
  std::vector<TransmissionDescription> transmissions;
  std::map<std::string, SurfaceDescription> surfaces;  // by link: its first collision's (URDF: its tags)
  // SDF: each link's collisions' surfaces, in the order of the link's collision_array.
  std::map<std::string, std::vector<SurfaceDescription>> collision_surfaces;
  std::vector<SensorDescription> sensors;
  std::vector<ModelPluginDescription> model_plugins;
  // From SDF (sdf_model.h): links that are frames only, not the model's links: the model frame
  // ("__model__") where it is not the root link's, and a joint's frame where SDF puts it apart from
  // its child link's (URDF's child frame is its joint's). Massless, folded by a fixed joint into the
  // body of a link, and not listed among the robot's links.
  std::set<std::string> frame_links;
  std::map<std::string, JointSpring> joint_springs;  // by joint
  // From SDF: each link's <gravity>, <kinematic>, <self_collide>; a link not listed has the defaults.
  std::map<std::string, LinkPhysics> link_physics;
  // SDF's <model><allow_auto_disable> (false in the model or a nested one): the model never sleeps.
  bool allow_auto_disable = true;
  // From SDF: each link's visuals' <material> and <transparency>, in the order of its visual_array
  // (visualMaterial).
  std::map<std::string, std::vector<VisualMaterial>> visual_materials;
  // From SDF: ball joints, which URDF has no type for: their URDF joints are FLOATING; the child turns
  // freely about the joint frame's origin (three rotations, no translation).
  std::set<std::string> ball_joints;
  // From SDF: joints whose positions are tied, held by one constraint row each (JointCoupling).
  std::vector<JointCouplingDescription> joint_couplings;
  // The format the model was written in. Gazebo treats the two apart in two ways the plant keeps: an
  // SDF model's collisions keep their SDF names ("model::link::collision") where sdformat's URDF
  // converter names a URDF's after their link ("link_collision"); and an SDF model (a world file's
  // box, spawn_model -sdf) publishes only what its plugins publish, where the plant gives a URDF
  // robot ground-truth odometry.
  enum class Format
  {
    Urdf,
    Sdf
  };
  Format format = Format::Urdf;
  // From SDF: the links no joint joins to the tree of the model's canonical link (its first link),
  // a tree each: Gazebo's free links, each moving on its own as a body of the same model (a race
  // track's floor and walls, a pile of boxes in one <model>). Each is a description of its own (its
  // links with their collisions, surfaces and sensors; its model frame the model's), which the world
  // simulates as a part of this model (World::spawn); the model's plugins and gazebo_ros_control stay
  // with the canonical link's tree, this one.
  std::vector<RobotDescription> other_trees;
  std::vector<std::string> warnings;                   // things read but not fully supported
  std::vector<std::string> errors;                     // things refused (logged as errors at spawn)
  std::string base_dir;  // relative mesh URIs resolve against it ("" for URDF text: the working directory)
};

// What cameras see on the index-th visual of `link`: its SDF <material> where the model is SDF;
// a URDF visual's <material><color> as its ambient and diffuse colour (VisualMaterial::colour; the
// plant's rule, docs/sdf.md); Gazebo's white (Material::gazeboWhite) without either.
VisualMaterial visualMaterial(const RobotDescription& robot, const std::string& link, size_t index,
                              const urdf::Visual& visual);

// The heaviest link the plant takes, kg: heavier, its contacts (single precision) lose it.
constexpr double kMaxLinkMass = 1e6;
// The largest length (an origin, a size) a URDF may give, m: beyond it single precision overflows.
constexpr double kMaxLength = 1e4;

// Parses URDF text. Throws DescriptionError with the parser's message for malformed input, for
// what urdfdom reported and left out (a mass of nan), for a negative or too large mass or a
// negative moment of inertia, and for lengths beyond kMaxLength. `base_dir`: the directory of the
// URDF file it came from, if any.
RobotDescription parseRobotDescription(const std::string& urdf_xml, const std::string& base_dir = "");

}  // namespace bullet_plant

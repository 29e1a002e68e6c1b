// bullet_plant.World: worlds from SDF (or from a WorldDescription, a world file parsed once), parameters, spawning, stepping, the log.
#include "bindings.h"

#include "bullet_plant/scene.h"

namespace bullet_plant
{
namespace python
{
namespace
{
// Deeper than this a parameter tree is a mistake (and its recursion would outgrow the stack).
constexpr size_t kMaxParamDepth = 100;

// `open`: the dicts and lists being converted on the way here, so that one holding itself is an
// error instead of an endless recursion (a crash).
Param toParam(const py::handle& obj, const std::string& where, std::vector<PyObject*>& open)
{
  if (py::isinstance<py::bool_>(obj))
    return Param::boolean(obj.cast<bool>());
  if (py::isinstance<py::int_>(obj))
    return Param::integer(obj.cast<long long>());
  if (py::isinstance<py::float_>(obj))
    return Param::real(obj.cast<double>());
  if (py::isinstance<py::str>(obj))
    return Param::string(obj.cast<std::string>());
  const bool is_dict = py::isinstance<py::dict>(obj);
  if (is_dict || py::isinstance<py::list>(obj) || py::isinstance<py::tuple>(obj))
  {
    if (std::find(open.begin(), open.end(), obj.ptr()) != open.end())
      throw py::value_error("parameter '" + where + "' contains itself (a dict or list holding a reference to "
                            "one of its parents); the parameter tree holds plain trees only");
    if (open.size() >= kMaxParamDepth)
      throw py::value_error("parameter '" + where + "' is nested deeper than " + std::to_string(kMaxParamDepth) +
                            " levels; the parameter tree takes no deeper");
    open.push_back(obj.ptr());
    Param out = Param::map();
    if (is_dict)
      for (auto item : obj.cast<py::dict>())
      {
        std::string key = py::str(item.first);
        out.set(key, toParam(item.second, (where == "/" ? where : where + "/") + key, open));
      }
    else
    {
      std::vector<Param> items;
      for (auto item : obj)
        items.push_back(toParam(item, where, open));
      out = Param::list(items);
    }
    open.pop_back();
    return out;
  }
  if (obj.is_none())
    return Param();
  throw py::type_error("parameter '" + where + "' has a type the parameter tree cannot hold: " +
                       std::string(py::str(obj.get_type())));
}
}  // namespace

void init_world(py::module_& m)
{
  // What a world file says, parsed once (MuJoCo's mjModel beside mjData): a racing environment makes a
  // world of its track at every reset, and parsing the peanut track's 232 walls was 3 of a reset's 6 ms.
  py::class_<WorldDescription, std::shared_ptr<WorldDescription>>(
      m, "WorldDescription",
      "a world file parsed once, to make any number of worlds from (World(description)); what a world "
      "file says is read when it is parsed, so a model it includes that changes on disk later is not seen")
      .def_static("from_file", [](const std::string& path) { return std::make_shared<WorldDescription>(parseWorldFile(path)); },
                  py::arg("path"), "an SDF world file parsed; its relative URIs resolve against the file's directory")
      .def_static("from_sdf", [](const std::string& sdf) { return std::make_shared<WorldDescription>(parseWorldDescription(sdf)); },
                  py::arg("sdf"), "SDF text parsed (relative URIs: relative to the working directory)")
      .def_property_readonly("name", [](const WorldDescription& d) { return d.name; }, "the world's <world name>")
      .def_property_readonly("file", [](const WorldDescription& d) { return d.file; }, "the world file ('' for text)")
      .def_property_readonly("max_step_size", [](const WorldDescription& d) { return d.max_step_size; },
                             "its physics step (s)");

  py::class_<PyWorld>(m, "World")
      .def(py::init([]() { return new PyWorld(emptyWorldDescription()); }), "an empty world with a ground plane")
      .def(py::init([](const WorldDescription& d) { return new PyWorld(d); }), py::arg("description"),
           "a world from a parsed world file (WorldDescription): the same world from_file makes, without parsing")
      .def_static("from_sdf", [](const std::string& sdf) { return new PyWorld(parseWorldDescription(sdf)); },
                  py::arg("sdf"), "a world from SDF text (relative URIs: relative to the working directory)")
      .def_static("from_file", [](const std::string& path) { return new PyWorld(parseWorldFile(path)); },
                  py::arg("path"), "a world from an SDF file; its relative URIs resolve against the file's directory")
      .def_property_readonly("file", [](PyWorld& w) { return w.world->description().file; },
                             "the world file ('' for a world from text)")
      .def("static_collisions", [](PyWorld& w) {
        static const char* kind_names[] = {"box", "cylinder", "sphere", "plane", "mesh", "capsule", "ellipsoid"};
        py::list out;
        for (const StaticCollision& c : w.world->description().collisions)
        {
          py::dict d;
          d["name"] = c.name;
          d["kind"] = kind_names[static_cast<int>(c.shape.kind)];
          d["pose"] = poseArray(c.pose);
          d["mesh_uri"] = c.shape.mesh_uri;
          d["mesh_file"] = c.shape.mesh_file;
          d["scale"] = std::vector<double>{c.shape.scale.x, c.shape.scale.y, c.shape.scale.z};
          // the shape's own dimensions (scene_json's keys): what a map of the walls draws
          putShapeDimensions(c.shape, [&](const char* key, const auto& value) { d[key] = value; });
          d["mu"] = c.mu;
          out.append(d);
        }
        return out;
      }, "the world's static collisions as described: name (model::link::collision), kind, pose (x y z qx qy qz qw), "
         "mesh_uri and mesh_file (as written, as resolved), scale, the kind's dimensions (box: size, full lengths; "
         "cylinder and capsule: radius, length; sphere: radius; ellipsoid: radii; plane: normal), mu")
      .def("scene_json", [](PyWorld& w) { return sceneJson(sceneOf(*w.world)); },
           "what a viewer draws: the world's static visuals and each robot's link visuals, the sun, ambient "
           "and background, as JSON (bullet_plant/scene.h; the node publishes it on /gazebo/scene)")
      .def_property("noise_seed", [](PyWorld& w) { return w.world->noiseSeed(); },
                    [](PyWorld& w, uint32_t seed) { w.world->setNoiseSeed(seed); },
                    "the seed of the noise of the sensors of robots spawned from now on (with their names); 0, the "
                    "default, seeds by the names alone")
      .def_property("echo", [](PyWorld& w) { return w.echo; }, [](PyWorld& w, bool on) { w.echo = on; },
                    "print warnings and errors to stderr as they happen (default True)")
      .def_property("frames_ahead", [](PyWorld& w) { return w.world->framesAhead(); },
                    [](PyWorld& w, bool ahead) {
                      py::gil_scoped_release release;  // setting it False waits for the frames rendering
                      w.world->setFramesAhead(ahead);
                    },
                    "camera frames still rendering when step() returns become the latest at a later step "
                    "(default False: step() returns with every frame due made)")
      .def_property("lockstep", [](PyWorld& w) { return w.world->lockstep(); },
                    [](PyWorld& w, bool lockstep) { w.world->setLockstep(lockstep); },
                    "every camera frame due renders, a step waiting for the camera's previous frame (default True, "
                    "Gazebo's --lockstep); False: a frame due while the camera's previous one still renders is "
                    "skipped (robot.sensor_skipped counts them), as the node runs")
      .def("messages", [](PyWorld& w, bool clear) {
        std::lock_guard<std::mutex> lock(w.mutex);
        std::vector<std::pair<std::string, std::string>> out(w.messages.begin(), w.messages.end());
        if (clear)
          w.messages.clear();
        return out;
      }, py::arg("clear") = false, "(level, text) of what the plant logged")
      .def("load_params", [](PyWorld& w, py::object tree, const std::string& ns) {
        if (py::isinstance<py::str>(tree))
        {
          py::object yaml = py::module_::import("yaml");
          py::object file = py::module_::import("builtins").attr("open")(tree);
          tree = yaml.attr("safe_load")(file);
          file.attr("close")();
        }
        if (!py::isinstance<py::dict>(tree))
          throw py::type_error("load_params takes a dict or the path of a YAML file holding one");
        std::vector<PyObject*> open;
        w.world->params().set(ns, toParam(tree, ns, open));
      }, py::arg("tree"), py::arg("namespace") = "/",
         "merge a dict or YAML file into the parameter tree under namespace, as `rosparam load`: its top "
         "key (e.g. tianracer) is the robot namespace the controller manager reads")
      .def_property("paused", [](PyWorld& w) { return w.world->paused(); },
                    [](PyWorld& w, bool p) { w.world->setPaused(p); },
                    "while paused, controller switches apply at once (step() still steps)")
      .def("get_param", [](PyWorld& w, const std::string& path) -> py::object {
        const Param* p = w.world->params().find(path);
        if (!p)
          return py::none();
        switch (p->type())
        {
          case Param::Type::Bool: return py::bool_(p->asBool());
          case Param::Type::Int: return py::int_(p->asInt());
          case Param::Type::Double: return py::float_(p->asDouble());
          case Param::Type::String: return py::str(p->asString());
          default: return py::str(p->describe());
        }
      })
      .def_property("time_step", [](PyWorld& w) { return w.world->timeStep(); },
                    [](PyWorld& w, double seconds) { w.world->setTimeStep(seconds); },
                    "s, a physics step (the SDF's <max_step_size>); ValueError outside the plant's range")
      .def_property_readonly("real_time_factor", [](PyWorld& w) { return w.world->description().real_time_factor; })
      .def_property_readonly("pace", [](PyWorld& w) { return w.world->description().pace(); },
                             "simulated seconds per wall second Gazebo keeps this world at: <real_time_update_rate> x "
                             "<max_step_size> (0: as fast as possible)")
      .def_property_readonly("time", [](PyWorld& w) { return w.world->time(); })
      .def_property("gravity", [](PyWorld& w) {
        const urdf::Vector3 g = w.world->gravity();
        return std::vector<double>{g.x, g.y, g.z};
      }, [](PyWorld& w, const std::vector<double>& g) {
        if (g.size() != 3)
          throw py::value_error("gravity is three numbers (m/s^2, world frame)");
        w.world->setGravity(urdf::Vector3(g[0], g[1], g[2]));
      }, "m/s^2, world frame (gazebo's set_physics_properties); setting it wakes every model asleep")
      .def_property_readonly("magnetic_field", [](PyWorld& w) {
        const urdf::Vector3& b = w.world->description().magnetic_field;
        return std::vector<double>{b.x, b.y, b.z};
      }, "the world's <magnetic_field>, tesla, world frame (SDF's default where it gives none)")
      .def_property_readonly("solver_iterations", [](PyWorld& w) { return w.world->solverIterations(); },
                             "the constraint solver's passes a step (<physics><ode><solver><iters>, else 10; "
                             "get_physics_properties' sor_pgs_iters)")
      .def_property_readonly("steps", [](PyWorld& w) { return w.world->steps(); })
      .def("spawn", [](PyWorld& w, const std::string& urdf, const std::string& name, std::vector<double> pose,
                       const std::string& ns, std::map<std::string, double> joints) {
        return w.handleTo(w.world->spawn(urdf, name, poseFromTuple(pose), ns, joints));
      }, py::arg("urdf"), py::arg("name"), py::arg("pose") = std::vector<double>(6, 0.0), py::arg("namespace") = "",
         py::arg("joints") = std::map<std::string, double>(), py::keep_alive<0, 1>(),
         "add a model from URDF or SDF text; raises DescriptionError naming what is wrong")
      .def("remove", [](PyWorld& w, const std::string& name) { return w.remove(name); }, py::arg("name"),
           "take a model out (a robot, or one of the world file's static models); a robot's handles then raise "
           "RobotRemovedError")
      .def_property_readonly("static_models", [](PyWorld& w) {
        py::list out;
        for (const StaticModelDescription& model : w.world->staticModels())
        {
          py::dict links;
          for (const StaticModelDescription::Link& link : model.links)
            links[py::str(link.name)] = poseArray(link.pose);
          out.append(py::dict(py::arg("name") = model.name, py::arg("pose") = poseArray(model.pose),
                              py::arg("links") = links));
        }
        return out;
      }, "the world file's static models where they are now, in file order: dicts of name, pose (x y z qx qy qz qw) "
         "and links (name: pose in the world)")
      .def("move_static_model", [](PyWorld& w, const std::string& name, const std::vector<double>& pose) {
        if (pose.size() != 7)
          throw py::value_error("move_static_model takes a pose of x y z qx qy qz qw");
        urdf::Pose p;
        p.position = urdf::Vector3(pose[0], pose[1], pose[2]);
        p.rotation = urdf::Rotation(pose[3], pose[4], pose[5], pose[6]);
        p.rotation.normalize();
        if (!w.world->moveStaticModel(name, p))
          throw py::key_error("no static model named '" + name + "'");
      }, py::arg("name"), py::arg("pose"),
         "gazebo_ros's set_model_state on a static model: a teleport, its collisions and what sensors see moved with it")
      .def("robot", [](PyWorld& w, const std::string& name) {
        Robot* r = w.world->robot(name);
        if (!r)
          throw py::key_error("no robot named '" + name + "'");
        return w.handleTo(*r);
      }, py::keep_alive<0, 1>())
      .def_property_readonly("robots", [](PyWorld& w) {
        std::vector<std::string> names;
        for (Robot* r : w.world->robots())
          names.push_back(r->name());
        return names;
      })
      .def("step", [](PyWorld& w, py::object count) {
        // bool is a subclass of int in Python; step(True) is a mistake, not one step.
        if (py::isinstance<py::bool_>(count) || !py::isinstance<py::int_>(count))
          throw py::type_error("step(n): n must be an int, not " + std::string(py::str(count.get_type())));
        long long n = count.cast<long long>();
        if (n < 0)
          throw py::value_error("step(n): n must not be negative, got " + std::to_string(n));
        // In chunks, so that Ctrl-C (checked between chunks, with the GIL held) stops a long run.
        const long long chunk = 1000;
        while (n > 0)
        {
          const int now = static_cast<int>(std::min(n, chunk));
          {
            py::gil_scoped_release release;
            w.world->step(now);
          }
          n -= now;
          if (PyErr_CheckSignals() != 0)
            throw py::error_already_set();
        }
      }, py::arg("n") = 1, "advance n fixed physics steps; Ctrl-C interrupts between chunks of 1000")
      .def("reset_simulation", [](PyWorld& w) { w.world->resetSimulation(); })
      .def("reset_world", [](PyWorld& w) { w.world->resetWorld(); })
      .def("contacts", [](PyWorld& w) {
        py::list out;
        for (const Contact& c : w.world->contacts())
        {
          py::dict d;
          d["collision1"] = c.collision1;
          d["collision2"] = c.collision2;
          d["position"] = xyzList(c.position);
          d["normal"] = xyzList(c.normal);
          d["force"] = xyzList(c.force);
          d["depth"] = c.depth;
          out.append(d);
        }
        return out;
      }, "every contact at the end of the last step: collision1, collision2 (model::link::collision), "
         "position, normal (out of collision2 into collision1), force on collision1 (N, world), depth (m)")
      .def("cast_ray", [](PyWorld& w, std::vector<double> origin, std::vector<double> direction, double max_range) {
        if (origin.size() != 3 || direction.size() != 3)
          throw py::value_error("origin and direction are 3-vectors");
        return w.world->castRay(urdf::Vector3(origin[0], origin[1], origin[2]),
                                urdf::Vector3(direction[0], direction[1], direction[2]), max_range, nullptr);
      });
}

}  // namespace python
}  // namespace bullet_plant

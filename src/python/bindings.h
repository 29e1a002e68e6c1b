// What the binding files share: the handles Python holds (a robot may be removed while Python
// still holds it), PyWorld, pose conversions, and each file's init_* function.
#pragma once

#include <algorithm>
#include <deque>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bullet_plant/controllers.h"
#include "bullet_plant/message_ports.h"
#include "bullet_plant/world.h"

namespace bullet_plant
{
namespace python
{
namespace py = pybind11;

inline urdf::Pose poseFromTuple(const std::vector<double>& v)
{
  if (v.size() != 6)
    throw py::value_error("pose must be (x, y, z, roll, pitch, yaw)");
  return poseFromXyzRpy(v[0], v[1], v[2], v[3], v[4], v[5]);
}

inline py::array_t<double> poseArray(const urdf::Pose& p)
{
  return py::array_t<double>(7, std::vector<double>{p.position.x, p.position.y, p.position.z, p.rotation.x,
                                                    p.rotation.y, p.rotation.z, p.rotation.w}.data());
}

// A stamped message's dict as every reading's starts: "stamp" (s) and, for a message with a header
// frame, "frame_id".
inline py::dict stampedDict(int64_t stamp_ns)
{
  py::dict d;
  d["stamp"] = double(stamp_ns) * 1e-9;
  return d;
}
inline py::dict stampedDict(int64_t stamp_ns, const std::string& frame_id)
{
  py::dict d = stampedDict(stamp_ns);
  d["frame_id"] = frame_id;
  return d;
}

inline std::vector<double> xyzList(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }
inline std::vector<double> xyzwList(const urdf::Rotation& q) { return {q.x, q.y, q.z, q.w}; }

// Raised by a Robot or ControllerManager handle whose robot World.remove took out.
struct RobotRemoved : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// What Python holds for a robot. The robot may be removed while Python still holds the handle, so
// the handle keeps no pointer of its own: it reads the robot from a cell its world empties on
// World.remove (and when the world goes), and every call through it checks the cell first.
struct RobotRef
{
  std::shared_ptr<Robot*> robot;
  std::string name;

  Robot& get() const
  {
    if (!*robot)
      throw RobotRemoved("robot '" + name + "' was removed from the world (World.remove): this handle and its "
                         "controller manager no longer refer to anything; spawn it again and use the new handle");
    return **robot;
  }
};

// The controller manager of a robot, reached through the robot's handle on every call.
struct ManagerRef
{
  RobotRef robot;
  ControllerManager& get() const;
};

// Binds f(Target&, args...) as a method of the handle type Ref: each call resolves the handle first.
template <typename Ref, typename F, typename Ret, typename Target, typename... Args>
auto throughHandle(F f, Ret (F::*)(Target&, Args...) const)
{
  return [f](const Ref& ref, Args... args) -> Ret { return f(ref.get(), std::forward<Args>(args)...); };
}
template <typename F>
auto onRobot(F f)
{
  return throughHandle<RobotRef>(f, &F::operator());
}
template <typename F>
auto onManager(F f)
{
  return throughHandle<ManagerRef>(f, &F::operator());
}

// A World plus the messages its log produced, kept for Python to read.
struct PyWorld
{
  explicit PyWorld(const WorldDescription& d)
  {
    // The sink from the world's first message on: what it says while it is built (its description's
    // warnings, the models it refused or spawned) is in messages() too.
    world.reset(new World(d, [this](LogLevel level, const std::string& m) {
      std::lock_guard<std::mutex> lock(mutex);
      messages.emplace_back(levelName(level), m);
      if (messages.size() > 10000)
        messages.pop_front();
      if (echo && level >= LogLevel::Warn)
        std::cerr << "[" << levelName(level) << "] " << m << std::endl;
    }));
  }
  ~PyWorld()
  {
    for (auto& entry : handle_cells)
      *entry.second = nullptr;
  }

  RobotRef handleTo(Robot& r)
  {
    std::shared_ptr<Robot*>& cell = handle_cells[r.name()];
    if (!cell)
      cell = std::make_shared<Robot*>(&r);
    return RobotRef{cell, r.name()};
  }
  bool remove(const std::string& name)
  {
    auto it = handle_cells.find(name);
    if (it != handle_cells.end())
    {
      *it->second = nullptr;
      handle_cells.erase(it);
    }
    return world->remove(name);
  }

  std::unique_ptr<World> world;
  std::map<std::string, std::shared_ptr<Robot*>> handle_cells;  // robot name -> what its handles read
  std::mutex mutex;
  std::deque<std::pair<std::string, std::string>> messages;
  bool echo = true;
};

// The robot's controller manager; ValueError when its URDF has no gazebo_ros_control block.
ControllerManager& managerOf(Robot& r);

inline Sensor& sensorOf(Robot& r, const std::string& name)
{
  Sensor* s = r.sensor(name);
  if (!s)
    throw py::key_error("robot '" + r.name() + "' has no simulated sensor '" + name + "'");
  return *s;
}

// The sensor as the type a reading needs; KeyError saying what it is not.
template <class SensorType>
SensorType& sensorAs(Robot& r, const std::string& name, const char* what)
{
  auto* typed = dynamic_cast<SensorType*>(&sensorOf(r, name));
  if (!typed)
    throw py::key_error("sensor '" + name + "' is not " + what);
  return *typed;
}

// controller_manager_bindings.cpp: the loaded controller of that name; KeyError when there is none.
Controller& controllerOf(ControllerManager& cm, const std::string& name);
// The controller's command port (its first input); KeyError when it takes no command.
Port& commandPortOf(Controller& c, const std::string& name);
void init_centerline(py::module_& m);
void init_car_batch(py::module_& m);

void init_world(py::module_& m);
py::class_<RobotRef> init_robot(py::module_& m);
void init_sensors(py::class_<RobotRef>& robot);
void init_model_plugins(py::class_<RobotRef>& robot);
// port_bindings.cpp: a Python value into an input port (a number: Float64, a list: Float64MultiArray,
// a pair: a Twist's linear.x and angular.z), the owner's answer; an output port's latest message as
// a dict, None before the first. TypeError for a message type Python cannot carry.
bool deliverToPort(Port& port, py::object value);
py::object latestOfPort(const Port& port);
void init_controller_manager(py::module_& m);

}  // namespace python
}  // namespace bullet_plant

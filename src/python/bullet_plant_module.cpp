// Python bindings of the plant: tianracer_description.bullet_plant. A thin layer: conversions only,
// one file per class (world, robot, sensors, controller manager), each an init_* function.
#include "bindings.h"
#include "bullet_plant/ray_kernels.h"

using namespace bullet_plant;
using namespace bullet_plant::python;

PYBIND11_MODULE(bullet_plant, m)
{
  m.doc() = "The Bullet plant that stands in for Gazebo + gazebo_ros_control, driven from Python.";

  py::register_exception<DescriptionError>(m, "DescriptionError", PyExc_ValueError);

  m.def("embree_isas", &embreeIsasThisCpuRuns,
        "the instruction sets of Embree's kernels this CPU runs, narrowest first: the values "
        "TIANRACER_EMBREE_ISA takes");
  m.def("embree_isa", [] {
    const EmbreeIsa isa = embreeIsa();
    return py::dict(py::arg("name") = isa.name, py::arg("forced") = isa.forced, py::arg("problem") = isa.problem);
  }, "the ISA of the kernels a world made now casts its sensors' rays with: {name, forced, problem}");
  py::register_exception<RobotRemoved>(m, "RobotRemovedError", PyExc_RuntimeError);

  py::class_<RobotRef> robot = init_robot(m);
  init_sensors(robot);
  init_model_plugins(robot);
  init_controller_manager(m);
  init_world(m);
  init_centerline(m);
  init_car_batch(m);
}

// bullet_plant.Robot's sensors: enabling them and their latest readings as dicts and arrays.
#include "bindings.h"

#include "bullet_plant/plugin_names.h"

namespace bullet_plant
{
namespace python
{
namespace
{
// What its gazebo_ros plugin calls things (plugin_names.h); its frame as without a tf_prefix
// parameter (there is no parameter server), as gazebo_ros_pkgs 2.9.2's plugins resolve it then.
std::string namespaceOf(const Robot& r, const Sensor& s)
{
  return pluginNamespace(s.description(), r.spawnNamespace(), r.name());
}

std::string frameOf(const Sensor& s)
{
  return pluginFrameId(s.description(), "");
}
}  // namespace

void init_sensors(py::class_<RobotRef>& robot)
{
  robot
      .def_property_readonly("sensors", onRobot([](Robot& r) {
        std::vector<std::string> names;
        for (Sensor* s : r.sensors())
          names.push_back(s->name());
        return names;
      }), "the simulated sensors of the URDF's <gazebo reference> blocks")
      .def("enable_sensor", onRobot([](Robot& r, const std::string& name, bool on) { sensorOf(r, name).setActive(on); }),
           py::arg("name"), py::arg("on") = true, "sensors work only while enabled (subscribed, in ROS)")
      .def("sensor_updates", onRobot([](Robot& r, const std::string& name) { return sensorOf(r, name).updates(); }))
      .def("sensor_skipped", onRobot([](Robot& r, const std::string& name) { return sensorOf(r, name).skipped(); }),
           "camera frames skipped out of lockstep (World.lockstep False): each was due while the previous one still rendered")
      .def("sensor_topic", onRobot([](Robot& r, const std::string& name) { return pluginTopic(sensorOf(r, name).description()); }))
      .def("sensor_namespace", onRobot([](Robot& r, const std::string& name) { return namespaceOf(r, sensorOf(r, name)); }),
           "the namespace the sensor's gazebo_ros plugin publishes in")
      .def("sensor_frame", onRobot([](Robot& r, const std::string& name) { return frameOf(sensorOf(r, name)); }),
           "the frame id the sensor's plugin publishes where no tf_prefix parameter is set")
      .def("imu", onRobot([](Robot& r, const std::string& name) -> py::object {
        Imu& imu = sensorAs<Imu>(r, name, "an IMU");
        if (!imu.hasReading())
          return py::none();
        const ImuReading& m = imu.latest();
        py::dict d = stampedDict(m.stamp_ns, frameOf(imu));
        d["orientation"] = xyzwList(m.orientation);
        d["angular_velocity"] = xyzList(m.angular_velocity);
        d["linear_acceleration"] = xyzList(m.linear_acceleration);
        return std::move(d);
      }), "the latest sensor_msgs/Imu fields (x y z w; IMU frame), or None before the first")
      .def("ground_truth", onRobot([](Robot& r, const std::string& name) -> py::object {
        GroundTruthOdometry& odometry = sensorAs<GroundTruthOdometry>(r, name, "a gazebo_ros_p3d plugin");
        if (!odometry.hasReading())
          return py::none();
        const GroundTruthReading& m = odometry.latest();
        py::dict d = stampedDict(m.stamp_ns, frameOf(odometry));
        d["child_frame_id"] = pluginChildFrameId(odometry.description());
        d["position"] = std::vector<double>{m.pose.position.x, m.pose.position.y, m.pose.position.z};
        d["orientation"] = std::vector<double>{m.pose.rotation.x, m.pose.rotation.y, m.pose.rotation.z, m.pose.rotation.w};
        d["linear"] = std::vector<double>{m.linear.x, m.linear.y, m.linear.z};
        d["angular"] = std::vector<double>{m.angular.x, m.angular.y, m.angular.z};
        return std::move(d);
      }), "the latest nav_msgs/Odometry fields of a gazebo_ros_p3d plugin, or None before the first")
      .def("contacts", onRobot([](Robot& r, const std::string& name) -> py::object {
        ContactSensor& sensor = sensorAs<ContactSensor>(r, name, "a contact sensor");
        if (!sensor.hasReading())
          return py::none();
        const ContactReading& m = sensor.latest();
        py::dict d = stampedDict(m.stamp_ns, frameOf(sensor));
        py::list states;
        for (const ContactState& s : m.states)
        {
          py::dict state;
          state["collision1_name"] = s.collision1;
          state["collision2_name"] = s.collision2;
          py::list positions, normals, depths, forces, torques;
          for (const ContactPoint& p : s.points)
          {
            positions.append(xyzList(p.position));
            normals.append(xyzList(p.normal));
            depths.append(p.depth);
            forces.append(xyzList(p.force));
            torques.append(xyzList(p.torque));
          }
          state["contact_positions"] = positions;
          state["contact_normals"] = normals;
          state["depths"] = depths;
          state["forces"] = forces;
          state["torques"] = torques;
          states.append(state);
        }
        d["states"] = states;
        return std::move(d);
      }), "the latest gazebo_msgs/ContactsState of a contact sensor as a dict (states: collision names, world "
          "positions and normals, depths, each point's force and torque on the sensor's body in its link frame), "
          "or None before the first")
      .def("scan", onRobot([](Robot& r, const std::string& name) -> py::object {
        Lidar& lidar = sensorAs<Lidar>(r, name, "a lidar");
        if (!lidar.hasScan())
          return py::none();
        const LaserScan& s = lidar.latest();
        py::dict d = stampedDict(s.stamp_ns, frameOf(lidar));
        d["angle_min"] = s.angle_min;
        d["angle_max"] = s.angle_max;
        d["angle_increment"] = s.angle_increment;
        d["time_increment"] = s.time_increment;
        d["scan_time"] = s.scan_time;
        d["range_min"] = s.range_min;
        d["range_max"] = s.range_max;
        d["ranges"] = py::array_t<float>(s.ranges.size(), s.ranges.data());
        return std::move(d);
      }), "the latest scan as a dict of sensor_msgs/LaserScan's fields, or None before the first")
      .def("image", onRobot([](Robot& r, const std::string& name) -> py::object {
        Camera& camera = sensorAs<Camera>(r, name, "a camera");
        if (!camera.hasFrame())
          return py::none();
        const CameraFrame& f = camera.latest();
        py::dict d = stampedDict(f.stamp_ns, frameOf(camera));
        d["width"] = f.width;
        d["height"] = f.height;
        d["K"] = std::vector<double>{f.fx, 0, f.cx, 0, f.fy, f.cy, 0, 0, 1};
        d["rgb"] = py::array_t<uint8_t>({f.height, f.width, 3}, f.rgb.data());
        if (!f.rgb16.empty())
          d["rgb16"] = py::array_t<uint16_t>({f.height, f.width, 3}, f.rgb16.data());
        if (camera.depthSensor())
        {
          d["depth"] = py::array_t<float>({f.height, f.width}, f.depth.data());
          d["points"] = py::array_t<float>({f.height, f.width, 3}, f.points.data());
        }
        return std::move(d);
      }), "the latest camera frame: rgb (H x W x 3 uint8), for a 16-bit <format> rgb16 (H x W x 3 uint16) as well, "
         "for depth cameras depth (H x W, m, NaN: no hit) and "
         "points (H x W x 3, optical frame); K the pinhole matrix; None before the first");
}

}  // namespace python
}  // namespace bullet_plant

// bullet_plant.CarBatch: N cars stepped together in one call: their controllers commanded, their
// worlds (one each, or several cars sharing one) stepped side by side on a TBB arena with the GIL
// released, and what a driving policy observes read back into arrays, with no Python between the
// cars: the lidar's ranges, the car's motion and, on a track, where it is along the centre line and
// its laps. Cars given a drive (set_drive) take actions, steering and speed shares, through the
// converter's Ackermann geometry (bullet_plant/ackermann_wheels.h). What the Gymnasium and
// PettingZoo environments (tianracer_description.racing) step on.
#include "bindings.h"
#include "centerline.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

#include "bullet_plant/ackermann_wheels.h"
#include "bullet_plant/controller_manager.h"

namespace bullet_plant
{
namespace python
{
namespace
{
// The columns of CarBatch.step's state rows, in order (CarBatch.STATE).
const std::vector<std::string> kStateColumns = {
    "x", "y", "yaw",                      // the root link in the world (m, rad)
    "speed", "lateral_speed", "yaw_rate",  // its velocity in its own heading (m/s, rad/s)
    "steer_left", "steer_right",          // the two steering joints' positions (rad)
    "steering",                           // their mean: what the car steers by (rad)
    "angular_velocity_x", "angular_velocity_y", "angular_velocity_z",           // the IMU's latest
    "linear_acceleration_x", "linear_acceleration_y", "linear_acceleration_z",  // (0 without one)
    "crashed",  // 1 when the car touches something other than the ground (a contact normal under 45 deg)
    "time",     // its world's simulated time (s)
    // On a centre line (NaN without one): Centerline.project of (x, y); the metres gained along the
    // line since the car was last read (Centerline.progress), and since it was set (their sum); its
    // laps since it was set (LapTimer: laps done, the last and the best lap's time, s, inf until timed).
    "centerline_s", "centerline_offset", "centerline_gained", "centerline_travelled",
    "lap_count", "last_lap_time", "best_lap_time",
};
const double kGroundNormalZ = std::sqrt(0.5);

struct WorldRows  // a world a step steps, and the rows of its cars in the step's results
{
  World* world;
  std::vector<size_t> rows;
  bool scans;  // a car's lidar scans within the step
};

struct CarSlot
{
  py::object world_handle;  // keeps the world alive while the batch holds its car
  World* world = nullptr;
  RobotRef robot;
  std::vector<InputPort<double>*> commands;  // the controllers' command ports, in the caller's order
  Lidar* lidar = nullptr;
  Imu* imu = nullptr;
  std::vector<std::string> steering_joints;
  std::shared_ptr<const Centerline> centerline;  // may be null
  std::ptrdiff_t segment = -1;  // of the centre line, the car's nearest when last read
  double s = 0;                 // and its arc length there
  double travelled = 0;         // along the line since set
  LapTimer laps;
  struct Drive  // set_drive's: an action's steering and speed shares are of these, through this geometry
  {
    AckermannGeometry geometry;
    double max_steering, max_speed;  // rad, m/s
  };
  std::optional<Drive> drive;
};

// The drive's four controllers' commands (rear left, rear right, steer left, steer right) for an
// action: steering and speed, each a share of the car's largest; the speed held within max_speed
// (ackermannWheelCommands holds the steering; a NaN stays NaN, which the controllers refuse).
void driveCommands(const CarSlot::Drive& drive, double steering_share, double speed_share, double out[4])
{
  const double speed = speed_share * drive.max_speed;
  const double held = speed > drive.max_speed ? drive.max_speed : speed < -drive.max_speed ? -drive.max_speed : speed;
  ackermannWheelCommands(held, steering_share * drive.max_steering, drive.max_steering, drive.geometry, out);
}

void spinPause()
{
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// Between two steps the arena's helper threads fall asleep, and waking one costs the next step
// 25-40 us on this VM (a futex and an interrupt to the other CPU): a tenth of a 4-car step on two
// threads (327 us a step called back to back, 364 us with 400 us of Python between the calls). As
// OpenMP runtimes spin their threads a while before they sleep (GOMP_SPINCOUNT, KMP_BLOCKTIME), the
// helpers spin after a step for twice the caller's recent gap between steps, and not at all when
// that gap is over kMaxLinger (then it is a policy's or a trainer's own work, which the other cores
// are better left to) or under kMinLinger.
class HelperLinger
{
public:
  static constexpr double kMaxLinger = 1e-3;  // s
  // Below this TBB's own spin before a worker sleeps covers the gap, and a spinning task enqueued at
  // every step only costs (the same loop with steps back to back: 337 us a step without, 400-500 with).
  static constexpr double kMinLinger = 20e-6;  // s

  explicit HelperLinger(tbb::task_arena& arena) : arena_(arena) { arena_.initialize(); }
  // The spinning tasks hold only the state they share with it, and stop.
  ~HelperLinger() { state_->stepping = true; }
  HelperLinger(const HelperLinger&) = delete;
  HelperLinger& operator=(const HelperLinger&) = delete;

  // As a step starts: the spinning ends, and the gap since the last step is measured.
  void stepStarts()
  {
    state_->stepping = true;
    const auto now = std::chrono::steady_clock::now();
    if (stepped_)
    {
      const double gap = std::chrono::duration<double>(now - last_end_).count();
      gap_ = gap_ < 0 ? gap : 0.7 * gap_ + 0.3 * gap;  // smoothed: one reset's gap does not stop it
    }
  }

  // As a step ends: each helper spins for the window the recent gaps ask for.
  void stepEnds()
  {
    stepped_ = true;
    last_end_ = std::chrono::steady_clock::now();
    const int helpers = arena_.max_concurrency() - 1;
    if (helpers <= 0 || gap_ < kMinLinger || gap_ > kMaxLinger)
      return;
    state_->stepping = false;
    const auto until = last_end_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                       std::chrono::duration<double>(std::min(2 * gap_, kMaxLinger)));
    for (int k = 0; k < helpers; ++k)
      arena_.enqueue([state = state_, until] {
        while (!state->stepping.load(std::memory_order_relaxed) && std::chrono::steady_clock::now() < until)
          spinPause();
      });
  }

private:
  struct State  // shared with the spinning tasks
  {
    std::atomic<bool> stepping{true};
  };
  tbb::task_arena& arena_;
  std::shared_ptr<State> state_ = std::make_shared<State>();
  bool stepped_ = false;
  std::chrono::steady_clock::time_point last_end_;
  double gap_ = -1;  // s, the recent gaps between steps, smoothed (-1: none yet)
};

class CarBatch
{
public:
  CarBatch(size_t count, int threads)
    : slots_(count), arena_(threads > 0 ? threads : tbb::task_arena::automatic), linger_(arena_)
  {
  }

  size_t size() const { return slots_.size(); }

  void set(size_t i, py::object world_handle, const RobotRef& robot_ref, const std::vector<std::string>& controllers,
           const std::string& lidar, const std::string& imu, const std::vector<std::string>& steering_joints,
           std::shared_ptr<const Centerline> centerline)
  {
    if (i >= slots_.size())
      throw py::index_error("car " + std::to_string(i) + " of a batch of " + std::to_string(slots_.size()));
    if (steering_joints.size() != 2)
      throw py::value_error("steering_joints are the left and right steering joints; got " +
                            std::to_string(steering_joints.size()));
    CarSlot slot;
    slot.world = world_handle.cast<PyWorld&>().world.get();
    slot.world_handle = std::move(world_handle);
    slot.robot = robot_ref;
    Robot& robot = robot_ref.get();
    ControllerManager& manager = managerOf(robot);
    for (const std::string& name : controllers)
    {
      auto* port = dynamic_cast<InputPort<double>*>(&commandPortOf(controllerOf(manager, name), name));
      if (!port)
        throw py::type_error("controller '" + name + "' does not take a number (std_msgs/Float64) as its command");
      slot.commands.push_back(port);
    }
    slot.lidar = &sensorAs<Lidar>(robot, lidar, "a lidar");
    slot.lidar->setActive(true);
    if (!imu.empty())
    {
      slot.imu = &sensorAs<Imu>(robot, imu, "an IMU");
      slot.imu->setActive(true);
    }
    double p, v, e;
    for (const std::string& joint : steering_joints)
      if (!robot.jointState(joint, p, v, e))
        throw py::key_error("robot '" + robot.name() + "' has no movable joint '" + joint + "'");
    slot.steering_joints = steering_joints;
    slot.centerline = std::move(centerline);
    if (slot.centerline)  // the whole line searched once; then near the last nearest segment
    {
      const urdf::Pose pose = robot.basePose();
      const Centerline::Projection along = slot.centerline->project(pose.position.x, pose.position.y);
      slot.segment = along.segment;
      slot.s = along.s;
      slot.laps = LapTimer(slot.centerline->length());
      slot.laps.restart(slot.centerline->progress(0.0, along.s), slot.world->time());
    }
    slots_[i] = std::move(slot);
  }

  void setDrive(size_t i, double wheelbase, double rear_track, double front_track, double wheel_radius,
                double max_steering, double max_speed)
  {
    CarSlot& car = slotOf(i);
    if (car.commands.size() != 4)
      throw py::value_error("car " + std::to_string(i) + " has " + std::to_string(car.commands.size()) +
                            " controllers; a drive commands four: rear left, rear right, steer left, steer right");
    for (const double v : {wheelbase, rear_track, front_track, wheel_radius, max_steering, max_speed})
      if (!(v > 0 && std::isfinite(v)))
        throw py::value_error("set_drive: the geometry, max_steering and max_speed are above 0; got " +
                              std::to_string(v));
    car.drive = CarSlot::Drive{{wheelbase, rear_track, front_track, wheel_radius}, max_steering, max_speed};
  }

  // commands: a row per car stepped (all, or those listed in `cars`), its controllers' commands;
  // returns (scans: a row of rays float32, state: a row of STATE float64) for each of them.
  py::tuple step(py::array_t<double, py::array::c_style | py::array::forcecast> commands, int steps,
                 std::optional<std::vector<size_t>> cars)
  {
    const std::vector<size_t> stepped = steppedCars(cars, steps);
    const size_t per_car = slots_[stepped[0]].commands.size();
    checkRows(commands, stepped.size(), per_car, "commands");
    const double* in = commands.data();
    for (size_t row = 0; row < stepped.size(); ++row)
      for (size_t c = 0; c < per_car; ++c)
        slots_[stepped[row]].commands[c]->deliver(in[row * per_car + c]);  // refused when not finite: the last one stays
    return run(stepped, steps);
  }

  // step with actions: a row of (steering, speed) shares per car, each given a drive (set_drive).
  py::tuple drive(py::array_t<double, py::array::c_style | py::array::forcecast> actions, int steps,
                  std::optional<std::vector<size_t>> cars)
  {
    const std::vector<size_t> stepped = steppedCars(cars, steps);
    for (size_t i : stepped)
      if (!slots_[i].drive)
        throw py::value_error("car " + std::to_string(i) + " has no drive (CarBatch.set_drive)");
    checkRows(actions, stepped.size(), 2, "actions");
    const double* in = actions.data();
    for (size_t row = 0; row < stepped.size(); ++row)
    {
      CarSlot& car = slots_[stepped[row]];
      double commands[4];
      driveCommands(*car.drive, in[2 * row], in[2 * row + 1], commands);
      for (size_t c = 0; c < 4; ++c)
        car.commands[c]->deliver(commands[c]);  // refused when not finite: the last one stays
    }
    return run(stepped, steps);
  }

private:
  CarSlot& slotOf(size_t i)
  {
    if (i >= slots_.size())
      throw py::index_error("car " + std::to_string(i) + " of a batch of " + std::to_string(slots_.size()));
    if (!slots_[i].world)
      throw py::value_error("car " + std::to_string(i) + " of the batch was never set (CarBatch.set)");
    return slots_[i];
  }

  // The cars a step steps (all, or those listed), checked before anything is delivered.
  std::vector<size_t> steppedCars(const std::optional<std::vector<size_t>>& cars, int steps)
  {
    std::vector<size_t> stepped = cars ? *cars : everyCar();
    for (size_t i : stepped)
      slotOf(i).robot.get();  // RobotRemovedError here, not on a worker thread
    if (stepped.empty())
      throw py::value_error("no car to step: `cars` is empty");
    if (steps < 1)
      throw py::value_error("steps must be at least 1; got " + std::to_string(steps));
    return stepped;
  }

  static void checkRows(const py::array_t<double, py::array::c_style | py::array::forcecast>& rows, size_t n,
                        size_t columns, const char* what)
  {
    if (rows.ndim() != 2 || size_t(rows.shape(0)) != n || size_t(rows.shape(1)) != columns)
      throw py::value_error(std::string(what) + " are " + std::to_string(n) + " x " + std::to_string(columns) +
                            " numbers");
  }

  // The stepped cars' worlds stepped `steps` times side by side, their cars read.
  py::tuple run(const std::vector<size_t>& stepped, int steps)
  {
    const size_t n = stepped.size();
    const SensorDescription& lidar = slots_[stepped[0]].lidar->description();
    const size_t rays = size_t(lidar.horizontal_samples) * size_t(lidar.vertical_samples);
    py::array_t<float> scans({n, rays});
    py::array_t<double> state({n, kStateColumns.size()});
    float* scan_out = scans.mutable_data();
    double* state_out = state.mutable_data();
    // Each world once, with the rows of the cars it holds: one task steps it, then reads them.
    std::vector<WorldRows> worlds;
    for (size_t row = 0; row < n; ++row)
    {
      World* world = slots_[stepped[row]].world;
      auto held = std::find_if(worlds.begin(), worlds.end(), [&](const WorldRows& w) { return w.world == world; });
      if (held == worlds.end())
        held = worlds.insert(worlds.end(), {world, {}, false});
      held->rows.push_back(row);
      const int64_t until_ns = world->timeNs() + steps * world->timeStepNs();
      held->scans = held->scans || slots_[stepped[row]].lidar->dueBy(until_ns);
    }
    // A world whose lidar scans within the step costs about twice one that does not (the Tianracer's
    // 40 Hz lidar scans in every second or third 10 ms step), and which worlds scan changes from step
    // to step once resets have moved their phases apart. The threads take the next world as they come
    // free, the scanning ones first, so that the dearest start first and the cheap ones fill in around
    // them (list scheduling, longest first). TBB's splitting of the index range paired the worlds by
    // index, two scanning worlds on one thread: 4 cars with their phases apart gained 1.44-1.53x from
    // a second thread that way, 1.61-1.75x this way (bench/racing_bench.py's vector env, interleaved).
    std::stable_partition(worlds.begin(), worlds.end(), [](const WorldRows& w) { return w.scans; });
    std::vector<std::string> errors(worlds.size());
    {
      py::gil_scoped_release release;
      linger_.stepStarts();
      std::atomic<size_t> next{0};
      arena_.execute([&] {
        tbb::parallel_for(0, arena_.max_concurrency(), 1, [&](int) {
          for (size_t w; (w = next.fetch_add(1, std::memory_order_relaxed)) < worlds.size();)
            try
            {
              worlds[w].world->step(steps);
              for (size_t row : worlds[w].rows)
                readCar(slots_[stepped[row]], rays, scan_out + row * rays, state_out + row * kStateColumns.size());
            }
            catch (const std::exception& e)
            {
              errors[w] = e.what();
            }
        }, tbb::simple_partitioner());
      });
      linger_.stepEnds();
    }
    for (size_t w = 0; w < worlds.size(); ++w)
      if (!errors[w].empty())
        throw std::runtime_error("the world of car " + std::to_string(stepped[worlds[w].rows[0]]) + ": " + errors[w]);
    return py::make_tuple(scans, state);
  }

  static void readCar(CarSlot& car, size_t rays, float* scan, double* state)
  {
    Robot& robot = car.robot.get();

    const std::vector<float>& ranges = car.lidar->latest().ranges;
    const auto range_max = float(car.lidar->description().range_max);
    for (size_t r = 0; r < rays; ++r)  // no return (inf), or no scan yet, reads as range_max
      scan[r] = r < ranges.size() ? std::min(ranges[r], range_max) : range_max;

    const urdf::Pose pose = robot.basePose();
    const Twist twist = robot.baseTwist();
    double roll, pitch, yaw;
    pose.rotation.getRPY(roll, pitch, yaw);
    const double c = std::cos(yaw), s = std::sin(yaw);
    double p, v, e;
    size_t k = 0;
    state[k++] = pose.position.x;
    state[k++] = pose.position.y;
    state[k++] = yaw;
    state[k++] = c * twist.linear[0] + s * twist.linear[1];
    state[k++] = -s * twist.linear[0] + c * twist.linear[1];
    state[k++] = twist.angular[2];
    double steering = 0;
    for (const std::string& joint : car.steering_joints)
    {
      robot.jointState(joint, p, v, e);
      state[k++] = p;
      steering += p / 2;
    }
    state[k++] = steering;
    const bool imu_read = car.imu && car.imu->hasReading();
    for (const urdf::Vector3* vector : {imu_read ? &car.imu->latest().angular_velocity : nullptr,
                                        imu_read ? &car.imu->latest().linear_acceleration : nullptr})
    {
      state[k++] = vector ? vector->x : 0.0;
      state[k++] = vector ? vector->y : 0.0;
      state[k++] = vector ? vector->z : 0.0;
    }
    bool crashed = false;
    for (const urdf::Vector3& normal : robot.contactNormals())
      crashed = crashed || std::abs(normal.z) < kGroundNormalZ;
    state[k++] = crashed ? 1.0 : 0.0;
    state[k++] = car.world->time();
    if (car.centerline)
    {
      const Centerline::Projection along = car.centerline->project(pose.position.x, pose.position.y, car.segment);
      state[k++] = along.s;
      state[k++] = along.offset;
      const double gained = car.centerline->progress(car.s, along.s);
      car.travelled += gained;
      state[k++] = gained;
      state[k++] = car.travelled;
      car.segment = along.segment;
      car.s = along.s;
      car.laps.read(car.travelled, car.world->time());
      state[k++] = double(car.laps.count());
      state[k++] = car.laps.last();
      state[k++] = car.laps.best();
    }
    else
      for (int column = 0; column < 7; ++column)
        state[k++] = std::numeric_limits<double>::quiet_NaN();
  }

  std::vector<size_t> everyCar() const
  {
    std::vector<size_t> all(slots_.size());
    for (size_t i = 0; i < all.size(); ++i)
      all[i] = i;
    return all;
  }

  std::vector<CarSlot> slots_;
  tbb::task_arena arena_;
  HelperLinger linger_;
};
}  // namespace

namespace
{
// An argument of wheel_command_rows: one value for every row, or one a row.
double rowValue(const py::array_t<double, py::array::c_style | py::array::forcecast>& a, py::ssize_t row)
{
  return a.size() == 1 ? a.data()[0] : a.data()[row];
}
}  // namespace

void init_car_batch(py::module_& m)
{
  m.def(
      "wheel_command_rows",
      [](py::array_t<double, py::array::c_style | py::array::forcecast> speed,
         py::array_t<double, py::array::c_style | py::array::forcecast> steering, double wheelbase, double rear_track,
         double front_track, double wheel_radius, py::array_t<double, py::array::c_style | py::array::forcecast> max_steering) {
        const py::ssize_t n = std::max({speed.size(), steering.size(), max_steering.size()});
        for (const auto* a : {&speed, &steering, &max_steering})
          if (a->size() != 1 && a->size() != n)
            throw py::value_error("wheel_command_rows: speed, steering and max_steering have one value or " +
                                  std::to_string(n) + " each; got " + std::to_string(a->size()));
        const AckermannGeometry g{wheelbase, rear_track, front_track, wheel_radius};
        py::array_t<double> rows({n, py::ssize_t(4)});
        double* out = rows.mutable_data();
        for (py::ssize_t i = 0; i < n; ++i)
          ackermannWheelCommands(rowValue(speed, i), rowValue(steering, i), rowValue(max_steering, i), g, out + 4 * i);
        return rows;
      },
      "Rows of rear left, rear right (rad/s), steer left, steer right (rad) for ground speeds (m/s) and ideal "
      "steering angles (rad), the steering held within max_steering (bullet_plant/ackermann_wheels.h); each of "
      "speed, steering and max_steering one value or one a row");

  py::class_<CarBatch>(m, "CarBatch",
                       "N cars, each in its own world, stepped in one call on `threads` threads (0: every core) "
                       "with the GIL released: commands in, the lidar's ranges and the car's state out. Between "
                       "steps called less than a millisecond apart the helper threads spin instead of sleeping")
      .def(py::init<size_t, int>(), py::arg("count"), py::arg("threads") = 0)
      .def("__len__", &CarBatch::size)
      .def("set", &CarBatch::set, py::arg("index"), py::arg("world"), py::arg("robot"), py::arg("controllers"),
           py::arg("lidar"), py::arg("imu") = "", py::arg("steering_joints"), py::arg("centerline") = nullptr,
           "car `index` is `robot` in `world`: commanded through these controllers' Float64 commands (their "
           "order is the commands' columns), its lidar and IMU (\"\": none) enabled and read, the "
           "steering joints' positions read and, with a Centerline, where it is along it")
      .def("set_drive", &CarBatch::setDrive, py::arg("index"), py::arg("wheelbase"), py::arg("rear_track"),
           py::arg("front_track"), py::arg("wheel_radius"), py::arg("max_steering"), py::arg("max_speed"),
           "car `index` (set, its controllers rear left, rear right, steer left, steer right) is driven by "
           "drive's actions: steering and speed, each a share of max_steering (rad, the ideal middle front "
           "wheel's) and max_speed (m/s), through this Ackermann geometry (m) as wheel_command_rows converts "
           "them, the speed held within max_speed")
      .def("drive", &CarBatch::drive, py::arg("actions"), py::arg("steps"), py::arg("cars") = py::none(),
           "step, with a row of (steering, speed) shares for each car stepped (every car's, or those listed in "
           "`cars`) converted to its controllers' commands by its drive (set_drive)")
      .def("step", &CarBatch::step, py::arg("commands"), py::arg("steps"), py::arg("cars") = py::none(),
           "each car's commands delivered, its world stepped `steps` times, all worlds side by side: every "
           "car's, or only those of the cars listed in `cars` (commands and results then a row each, in that "
           "order); (scans: rows of the latest scan's ranges, float32, no return as range_max; state: rows of "
           "len(STATE) float64)")
      .def_property_readonly_static("STATE", [](py::object) { return kStateColumns; });
}

}  // namespace python
}  // namespace bullet_plant

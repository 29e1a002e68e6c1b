// One robot's sensors on ROS as their gazebo_ros plugins publish them: sensor_msgs LaserScan, Image,
// CameraInfo, PointCloud2 and Imu, nav_msgs/Odometry (gazebo_ros_p3d), each in its plugin's
// namespace and computing only while its topics have subscribers. Runs on the simulation thread.
#pragma once

#include <cstdint>
#include <vector>

#include <ros/ros.h>

namespace bullet_plant
{
class Robot;
class Sensor;
class Lidar;
class Camera;
class Imu;
class GroundTruthOdometry;

class SensorPublishers
{
public:
  explicit SensorPublishers(Robot& robot);
  // Turns each sensor on while someone subscribes to one of its topics, off otherwise (and logs it).
  void updateSubscriptions();
  // After a step: what each sensor computed since the last call.
  void publish();

private:
  struct LidarTopic
  {
    Lidar* lidar;
    ros::Publisher scan;
    uint64_t updates = 0;  // the lidar's update count last published
  };
  struct CameraTopics
  {
    Camera* camera;
    ros::Publisher image, info, depth, depth_info, points;
    uint64_t updates = 0;
  };
  struct ImuTopic
  {
    Imu* imu;
    ros::Publisher pub;
    uint64_t updates = 0;
  };
  struct GroundTruthTopic
  {
    GroundTruthOdometry* odometry;
    ros::Publisher pub;
    uint64_t updates = 0;
  };
  void setActive(Sensor* sensor, bool active);
  void publishScans();
  void publishCameras();
  void publishImus();
  void publishGroundTruth();

  Robot& robot_;
  std::vector<LidarTopic> lidars_;
  std::vector<CameraTopics> cameras_;
  std::vector<ImuTopic> imus_;
  std::vector<GroundTruthTopic> ground_truths_;
};

}  // namespace bullet_plant

// One robot's lidars and cameras on ROS: sensor_msgs LaserScan, Image, CameraInfo and PointCloud2,
// each sensor computing only while its topics have subscribers. Runs on the simulation thread.
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

class SensorPublishers
{
public:
  SensorPublishers(Robot& robot, ros::NodeHandle& nh);
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
  void setActive(Sensor* sensor, bool active);
  void publishScans();
  void publishCameras();

  Robot& robot_;
  std::vector<LidarTopic> lidars_;
  std::vector<CameraTopics> cameras_;
};

}  // namespace bullet_plant

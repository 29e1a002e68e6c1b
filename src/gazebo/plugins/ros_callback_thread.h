// What gazebo_ros_pkgs' plugins keep beside the Gazebo plugin they derive from: a ROS node handle
// whose subscriptions are served on a queue of their own by a thread of their own, as upstream's
// plugins serve theirs (a message comes whatever the node's spinners do). Destroyed, it stops taking
// messages and joins its thread before the plugin goes.
#pragma once

#include <string>
#include <thread>
#include <utility>

#include <boost/function.hpp>
#include <ros/callback_queue.h>
#include <ros/ros.h>

namespace gazebo
{
class RosCallbackThread
{
public:
  explicit RosCallbackThread(const std::string& robot_namespace) : node_(robot_namespace)
  {
    node_.setCallbackQueue(&queue_);
    thread_ = std::thread([this] {
      while (node_.ok())
        queue_.callAvailable(ros::WallDuration(0.01));
    });
  }
  ~RosCallbackThread()
  {
    queue_.clear();
    queue_.disable();
    node_.shutdown();
    thread_.join();
  }
  RosCallbackThread(const RosCallbackThread&) = delete;
  RosCallbackThread& operator=(const RosCallbackThread&) = delete;

  // `topic` (relative to the namespace), a queue of one, served on this thread.
  template <class Message>
  ros::Subscriber subscribe(const std::string& topic,
                            const boost::function<void(const typename Message::ConstPtr&)>& callback)
  {
    ros::SubscribeOptions options =
        ros::SubscribeOptions::create<Message>(topic, 1, callback, ros::VoidPtr(), &queue_);
    return node_.subscribe(options);
  }

  // The node handle whose callbacks (a dynamic_reconfigure server's services among them) this thread serves.
  ros::NodeHandle& node() { return node_; }

private:
  ros::NodeHandle node_;
  ros::CallbackQueue queue_;
  std::thread thread_;
};
}  // namespace gazebo

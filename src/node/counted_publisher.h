// A publisher that knows, without asking roscpp, whether anyone subscribes: roscpp keeps the count
// through the publisher's connect and disconnect callbacks (and calls connect for the subscribers a
// topic already has when it is advertised again). Asking roscpp (getNumSubscribers) searches every
// topic the node advertises, under its lock; an output asked after every step would pay that for
// each robot at each step. What nobody subscribes to is not built, as Gazebo's sensors publish
// lazily.
#pragma once

#include <atomic>
#include <memory>
#include <string>

#include <ros/ros.h>

namespace bullet_plant
{
class CountedPublisher
{
public:
  CountedPublisher() = default;

  template <class Msg>
  static CountedPublisher advertise(ros::NodeHandle nh, const std::string& topic, uint32_t queue_size,
                                    bool latch = false)
  {
    CountedPublisher counted;
    std::shared_ptr<std::atomic<int>> count = counted.subscribers_;
    counted.publisher_ = nh.advertise<Msg>(
        topic, queue_size, [count](const ros::SingleSubscriberPublisher&) { ++*count; },
        [count](const ros::SingleSubscriberPublisher&) { --*count; }, ros::VoidConstPtr(), latch);
    return counted;
  }

  const ros::Publisher& publisher() const { return publisher_; }
  // Whether someone subscribes (as roscpp told the callbacks so far).
  bool subscribed() const { return publisher_ && *subscribers_ > 0; }
  explicit operator bool() const { return static_cast<bool>(publisher_); }

private:
  ros::Publisher publisher_;
  std::shared_ptr<std::atomic<int>> subscribers_ = std::make_shared<std::atomic<int>>(0);
};

}  // namespace bullet_plant

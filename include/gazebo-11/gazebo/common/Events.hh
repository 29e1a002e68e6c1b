// event::Events: the simulation's events a plugin connects to (ConnectWorldUpdateBegin and the
// rest), one of each for the process, as in Gazebo. Which of them the plant signals, and when:
// docs/gazebo_api.md.
#pragma once

#include <string>

#include "gazebo/common/Event.hh"
#include "gazebo/common/UpdateInfo.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace event
{
class GZ_COMMON_VISIBLE Events
{
public:
  template <typename T>
  static ConnectionPtr ConnectPause(T subscriber) { return pause.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectStep(T subscriber) { return step.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectStop(T subscriber) { return stop.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectWorldCreated(T subscriber) { return worldCreated.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectDeleteEntity(T subscriber) { return deleteEntity.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectWorldUpdateBegin(T subscriber) { return worldUpdateBegin.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectWorldUpdateEnd(T subscriber) { return worldUpdateEnd.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectBeforePhysicsUpdate(T subscriber) { return beforePhysicsUpdate.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectWorldReset(T subscriber) { return worldReset.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectTimeReset(T subscriber) { return timeReset.Connect(subscriber); }
  // The rendering sensors' cycle, as Gazebo's sensor manager runs it while the world has one (a
  // camera, depth, multicamera or GPU ray sensor): preRender, preRenderEnded, render, postRender,
  // then the sensors' updates. The plant signals it after each step, before it decides which
  // sensors measure in the next (a plugin that activates its camera in PreRender gets the next
  // frame: gazebo_ros_triggered_camera's trigger).
  template <typename T>
  static ConnectionPtr ConnectPreRender(T subscriber) { return preRender.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectPreRenderEnded(T subscriber) { return preRenderEnded.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectRender(T subscriber) { return render.Connect(subscriber); }
  template <typename T>
  static ConnectionPtr ConnectPostRender(T subscriber) { return postRender.Connect(subscriber); }

  static EventT<void(bool)> pause;
  static EventT<void()> step;
  static EventT<void()> stop;
  static EventT<void(std::string)> worldCreated;
  static EventT<void(std::string)> deleteEntity;
  static EventT<void(const common::UpdateInfo&)> worldUpdateBegin;
  static EventT<void()> worldUpdateEnd;
  static EventT<void(const common::UpdateInfo&)> beforePhysicsUpdate;
  static EventT<void()> worldReset;
  static EventT<void()> timeReset;
  static EventT<void()> preRender;
  static EventT<void()> preRenderEnded;
  static EventT<void()> render;
  static EventT<void()> postRender;
};
}  // namespace event
}  // namespace gazebo

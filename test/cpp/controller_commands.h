// What the node does with a controller's topics, for gtests that drive controllers directly.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/controllers.h"

namespace bullet_plant
{
// A message on the controller's command topic of that type: false when it has none or refuses it.
template <class Msg>
bool command(Controller& c, const Msg& m)
{
  InputPort<Msg>* in = c.input<Msg>();
  return in && in->deliver(m);
}

inline bool twist(Controller& c, double linear_x, double angular_z) { return command(c, TwistCommand{linear_x, angular_z}); }

// The topic the controller takes Msg on, "" for none.
template <class Msg>
std::string commandTopic(const Controller& c)
{
  const InputPort<Msg>* in = c.input<Msg>();
  return in ? in->topic() : "";
}

// What it published of Msg since the last take.
template <class Msg>
std::vector<Msg> take(Controller& c)
{
  OutputPort<Msg>* out = c.output<Msg>();
  return out ? out->take() : std::vector<Msg>();
}

}  // namespace bullet_plant

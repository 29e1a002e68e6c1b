// physics::Contact (gazebo/physics/Contact.hh).
#include "gazebo/physics/Contact.hh"

#include <algorithm>
#include <sstream>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/physics/Collision.hh"
#include "gazebo/physics/PhysicsIface.hh"
#include "gazebo/physics/World.hh"

namespace gazebo
{
namespace physics
{
Contact& Contact::operator=(const msgs::Contact& contact)
{
  count = 0;
  collision1 = collision2 = nullptr;
  try
  {
    world = get_world(contact.world());
  }
  catch (const common::Exception&)
  {
    world.reset();
  }
  if (world)
  {
    collision1 = boost::dynamic_pointer_cast<Collision>(world->EntityByName(contact.collision1())).get();
    collision2 = boost::dynamic_pointer_cast<Collision>(world->EntityByName(contact.collision2())).get();
  }
  else
    gzwarn << "World: " << contact.world() << " not found,contact collision pointers will be NULL";
  const int points = std::min(contact.position_size(), MAX_CONTACT_JOINTS);
  for (int j = 0; j < points; ++j)
  {
    positions[j] = msgs::ConvertIgn(contact.position(j));
    normals[j] = j < contact.normal_size() ? msgs::ConvertIgn(contact.normal(j)) : ignition::math::Vector3d();
    depths[j] = j < contact.depth_size() ? contact.depth(j) : 0.0;
    if (j < contact.wrench_size())
    {
      const msgs::JointWrench& w = contact.wrench(j);
      wrench[j].body1Force = msgs::ConvertIgn(w.body_1_wrench().force());
      wrench[j].body2Force = msgs::ConvertIgn(w.body_2_wrench().force());
      wrench[j].body1Torque = msgs::ConvertIgn(w.body_1_wrench().torque());
      wrench[j].body2Torque = msgs::ConvertIgn(w.body_2_wrench().torque());
    }
    ++count;
  }
  time = msgs::Convert(contact.time());
  return *this;
}

void Contact::FillMsg(msgs::Contact& msg) const
{
  msg.set_world(world ? world->Name() : "");
  msg.set_collision1(collision1 ? collision1->GetScopedName() : "");
  msg.set_collision2(collision2 ? collision2->GetScopedName() : "");
  msgs::Set(msg.mutable_time(), time);
  msg.clear_position();
  msg.clear_normal();
  msg.clear_depth();
  msg.clear_wrench();
  for (int j = 0; j < count; ++j)
  {
    msgs::Set(msg.add_position(), positions[j]);
    msgs::Set(msg.add_normal(), normals[j]);
    msg.add_depth(depths[j]);
    msgs::JointWrench* w = msg.add_wrench();
    w->set_body_1_name(collision1 ? collision1->GetScopedName() : "");
    w->set_body_1_id(0);
    w->set_body_2_name(collision2 ? collision2->GetScopedName() : "");
    w->set_body_2_id(0);
    msgs::Set(w->mutable_body_1_wrench()->mutable_force(), wrench[j].body1Force);
    msgs::Set(w->mutable_body_1_wrench()->mutable_torque(), wrench[j].body1Torque);
    msgs::Set(w->mutable_body_2_wrench()->mutable_force(), wrench[j].body2Force);
    msgs::Set(w->mutable_body_2_wrench()->mutable_torque(), wrench[j].body2Torque);
  }
}

std::string Contact::DebugString() const
{
  std::ostringstream out;
  out << "Collision 1[" << (collision1 ? collision1->GetScopedName() : "") << "]\n"
      << "Collision 2[" << (collision2 ? collision2->GetScopedName() : "") << "]\n"
      << "Time[" << time << "]\n"
      << "Contact Count[" << count << "]\n";
  for (int j = 0; j < count; ++j)
    out << "--- Contact[" << j << "]\n"
        << "  Depth[" << depths[j] << "]\n"
        << "  Position[" << positions[j] << "]\n"
        << "  Normal[" << normals[j] << "]\n"
        << "  Force1[" << wrench[j].body1Force << "]\n"
        << "  Force2[" << wrench[j].body2Force << "]\n"
        << "  Torque1[" << wrench[j].body1Torque << "]\n"
        << "  Torque2[" << wrench[j].body2Torque << "]\n";
  return out.str();
}

void Contact::Reset()
{
  count = 0;
  collision1 = collision2 = nullptr;
}
}  // namespace physics
}  // namespace gazebo

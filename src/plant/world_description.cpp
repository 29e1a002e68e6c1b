#include "bullet_plant/world_description.h"

#include <cmath>

#include <tinyxml2.h>

#include "bullet_plant/robot_description.h"
#include "xml_util.h"

namespace bullet_plant
{
namespace
{
StaticCollision groundPlane(const urdf::Pose& pose)
{
  StaticCollision ground;
  ground.name = "ground_plane::link::collision";
  ground.shape.kind = Shape::Kind::Plane;
  ground.pose = pose;
  ground.colour = {0.7f, 0.7f, 0.7f, 1.0f};
  return ground;
}

Shape readGeometry(const tinyxml2::XMLElement* geometry, const std::string& where)
{
  Shape shape;
  if (auto* box = geometry->FirstChildElement("box"))
  {
    shape.kind = Shape::Kind::Box;
    std::vector<double> size = xml::numbers(xml::childText(box, "size", "1 1 1"), 3, where + " <box><size>");
    for (int i = 0; i < 3; ++i)
    {
      if (size[i] <= 0)
        throw DescriptionError(where + ": box sizes must be positive");
      shape.box_size[i] = size[i];
    }
  }
  else if (auto* cylinder = geometry->FirstChildElement("cylinder"))
  {
    shape.kind = Shape::Kind::Cylinder;
    shape.radius = xml::childDouble(cylinder, "radius", 1.0);
    shape.length = xml::childDouble(cylinder, "length", 1.0);
    if (shape.radius <= 0 || shape.length <= 0)
      throw DescriptionError(where + ": cylinder radius and length must be positive");
  }
  else if (auto* sphere = geometry->FirstChildElement("sphere"))
  {
    shape.kind = Shape::Kind::Sphere;
    shape.radius = xml::childDouble(sphere, "radius", 1.0);
    if (shape.radius <= 0)
      throw DescriptionError(where + ": sphere radius must be positive");
  }
  else if (auto* plane = geometry->FirstChildElement("plane"))
  {
    shape.kind = Shape::Kind::Plane;
    std::vector<double> n = xml::numbers(xml::childText(plane, "normal", "0 0 1"), 3, where + " <plane><normal>");
    double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (norm < 1e-9)
      throw DescriptionError(where + ": plane normal must not be zero");
    shape.normal = urdf::Vector3(n[0] / norm, n[1] / norm, n[2] / norm);
  }
  else
  {
    const tinyxml2::XMLElement* first = geometry->FirstChildElement();
    throw DescriptionError(where + ": geometry <" + std::string(first ? first->Name() : "") +
                           "> is not supported (box, cylinder, sphere, plane)");
  }
  return shape;
}

Rgba readColour(const tinyxml2::XMLElement* visual)
{
  Rgba colour;
  const tinyxml2::XMLElement* material = visual ? visual->FirstChildElement("material") : nullptr;
  if (!material)
    return colour;
  std::string text = xml::childText(material, "diffuse", xml::childText(material, "ambient", ""));
  if (text.empty())
    return colour;
  std::vector<double> c = xml::numbers(text, 4, "<material><diffuse>");
  return {float(c[0]), float(c[1]), float(c[2]), float(c[3])};
}

void readModel(const tinyxml2::XMLElement* model, WorldDescription& world)
{
  std::string model_name = model->Attribute("name") ? model->Attribute("name") : "model";
  if (xml::childText(model, "static", "false") != "true" && xml::childText(model, "static", "0") != "1")
    world.warnings.push_back("model '" + model_name + "' is not static; the plant keeps world models still");
  urdf::Pose model_pose = xml::parseSdfPose(xml::childText(model, "pose", ""));
  for (auto* link = model->FirstChildElement("link"); link; link = link->NextSiblingElement("link"))
  {
    std::string link_name = link->Attribute("name") ? link->Attribute("name") : "link";
    urdf::Pose link_pose = compose(model_pose, xml::parseSdfPose(xml::childText(link, "pose", "")));
    const tinyxml2::XMLElement* first_visual = link->FirstChildElement("visual");
    for (auto* c = link->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision"))
    {
      StaticCollision collision;
      collision.name = model_name + "::" + link_name + "::" + (c->Attribute("name") ? c->Attribute("name") : "collision");
      const tinyxml2::XMLElement* geometry = c->FirstChildElement("geometry");
      if (!geometry)
        throw DescriptionError("collision '" + collision.name + "' has no <geometry>");
      collision.shape = readGeometry(geometry, "collision '" + collision.name + "'");
      collision.pose = compose(link_pose, xml::parseSdfPose(xml::childText(c, "pose", "")));
      collision.mu = xml::childDouble(c, "surface/friction/ode/mu", 1.0);
      collision.colour = readColour(first_visual);
      world.collisions.push_back(collision);
    }
  }
}

void readInclude(const tinyxml2::XMLElement* include, WorldDescription& world)
{
  std::string uri = xml::childText(include, "uri", "");
  urdf::Pose pose = xml::parseSdfPose(xml::childText(include, "pose", ""));
  if (uri == "model://ground_plane")
    world.collisions.push_back(groundPlane(pose));
  else if (uri == "model://sun")
    ;  // the default light direction is the sun's
  else
    world.warnings.push_back("<include> of '" + uri + "' is not available here (only model://ground_plane and "
                             "model://sun); skipped");
}

}  // namespace

WorldDescription emptyWorldDescription()
{
  WorldDescription world;
  world.collisions.push_back(groundPlane(urdf::Pose()));
  return world;
}

WorldDescription parseWorldDescription(const std::string& sdf_xml)
{
  tinyxml2::XMLDocument doc;
  if (doc.Parse(sdf_xml.c_str(), sdf_xml.size()) != tinyxml2::XML_SUCCESS)
    throw DescriptionError(std::string("SDF is not well-formed XML: ") + doc.ErrorStr());
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  const tinyxml2::XMLElement* w = sdf ? sdf->FirstChildElement("world") : nullptr;
  if (!w)
    throw DescriptionError("SDF has no <sdf><world> element");

  WorldDescription world;
  world.name = w->Attribute("name") ? w->Attribute("name") : "default";
  if (auto* physics = w->FirstChildElement("physics"))
  {
    world.max_step_size = xml::childDouble(physics, "max_step_size", world.max_step_size);
    world.real_time_factor = xml::childDouble(physics, "real_time_factor", world.real_time_factor);
    if (world.max_step_size <= 0 || world.max_step_size > 0.1)
      throw DescriptionError("<physics><max_step_size> " + std::to_string(world.max_step_size) +
                             " is out of range (0, 0.1] s");
  }
  std::string gravity = xml::childText(w, "gravity", "");
  if (!gravity.empty())
  {
    std::vector<double> g = xml::numbers(gravity, 3, "<gravity>");
    world.gravity = urdf::Vector3(g[0], g[1], g[2]);
  }
  for (auto* light = w->FirstChildElement("light"); light; light = light->NextSiblingElement("light"))
    if (light->Attribute("type") && std::string(light->Attribute("type")) == "directional")
    {
      std::vector<double> d = xml::numbers(xml::childText(light, "direction", "-0.5 0.1 -0.9"), 3, "<light><direction>");
      world.light_direction = urdf::Vector3(d[0], d[1], d[2]);
    }
  for (auto* e = w->FirstChildElement(); e; e = e->NextSiblingElement())
  {
    std::string tag = e->Name();
    if (tag == "model")
      readModel(e, world);
    else if (tag == "include")
      readInclude(e, world);
  }
  bool has_plane = false;
  for (const StaticCollision& c : world.collisions)
    has_plane = has_plane || c.shape.kind == Shape::Kind::Plane;
  if (!has_plane)
    world.collisions.push_back(groundPlane(urdf::Pose()));
  return world;
}

}  // namespace bullet_plant

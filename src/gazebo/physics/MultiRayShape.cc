// physics::MultiRayShape (gazebo/physics/MultiRayShape.hh): a ray sensor's rays over the scan its
// simulator cast.
#include "gazebo/physics/MultiRayShape.hh"

#include <cmath>
#include <limits>

#include "gazebo/common/Console.hh"

namespace gazebo
{
namespace physics
{
namespace
{
// A child of `parent` as sdformat gives it: the element's value, or SDF's default where it is not
// written (GetElement adds it from the spec).
template <typename T>
T valueOf(const sdf::ElementPtr& parent, const std::string& name)
{
  return parent->GetElement(name)->Get<T>();
}
}  // namespace

MultiRayShape::MultiRayShape(CollisionPtr parent) : Shape(std::move(parent)) { AddType(MULTIRAY_SHAPE); }

MultiRayShape::~MultiRayShape() = default;

void MultiRayShape::Load(sdf::ElementPtr sensor)
{
  const sdf::ElementPtr ray = sensor->GetName() == "ray" ? sensor : sensor->GetElement("ray");
  const sdf::ElementPtr scan = ray->GetElement("scan");
  const sdf::ElementPtr horizontal = scan->GetElement("horizontal");
  samples_ = static_cast<int>(valueOf<unsigned int>(horizontal, "samples"));
  resolution_ = valueOf<double>(horizontal, "resolution");
  min_angle_ = valueOf<double>(horizontal, "min_angle");
  max_angle_ = valueOf<double>(horizontal, "max_angle");
  if (scan->HasElement("vertical"))  // as Gazebo's: a planar scan without it
  {
    const sdf::ElementPtr vertical = scan->GetElement("vertical");
    vertical_samples_ = static_cast<int>(valueOf<unsigned int>(vertical, "samples"));
    vertical_resolution_ = valueOf<double>(vertical, "resolution");
    vertical_min_angle_ = valueOf<double>(vertical, "min_angle");
    vertical_max_angle_ = valueOf<double>(vertical, "max_angle");
  }
  const sdf::ElementPtr range = ray->GetElement("range");
  range_min_ = valueOf<double>(range, "min");
  range_max_ = valueOf<double>(range, "max");
  range_resolution_ = valueOf<double>(range, "resolution");
  ranges_.assign(RayCount(), std::numeric_limits<float>::infinity());
}

double MultiRayShape::GetRange(unsigned int index)
{
  if (index >= ranges_.size())
  {
    gzerr << "Invalid ray index[" << index << "]: the shape has " << ranges_.size() << " rays\n";
    return 0.0;
  }
  // Gazebo's rays are as long as what they hit, at most the maximum range, from the minimum on.
  const double r = ranges_[index];
  return std::isinf(r) ? (r > 0 ? range_max_ : range_min_) : r;
}

double MultiRayShape::GetRetro(unsigned int index)
{
  if (index >= ranges_.size())
    gzerr << "Invalid ray index[" << index << "]: the shape has " << ranges_.size() << " rays\n";
  return 0.0;
}

int MultiRayShape::GetFiducial(unsigned int index)
{
  if (index >= ranges_.size())
    gzerr << "Invalid ray index[" << index << "]: the shape has " << ranges_.size() << " rays\n";
  return -1;
}

void MultiRayShape::Update() { new_laser_scans_(); }

}  // namespace physics
}  // namespace gazebo

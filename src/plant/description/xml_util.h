// Small helpers for reading URDF extension and SDF elements with tinyxml2. Private to the plant.
#pragma once

#include <string>

#include <tinyxml2.h>
#include <urdf_model/pose.h>

namespace bullet_plant
{
namespace xml
{
std::string trimmed(const std::string& s);
// Child element by a relative path "a/b"; nullptr when missing.
const tinyxml2::XMLElement* child(const tinyxml2::XMLElement* e, const std::string& path);
std::string childText(const tinyxml2::XMLElement* e, const std::string& path, const std::string& fallback);
// Numeric child; throws DescriptionError naming the element when the text is not a number.
double childDouble(const tinyxml2::XMLElement* e, const std::string& path, double fallback);
// Whitespace-separated numbers; throws DescriptionError when there are not exactly n.
std::vector<double> numbers(const std::string& text, size_t n, const std::string& what);
// SDF "x y z roll pitch yaw" (empty: identity).
urdf::Pose parseSdfPose(const std::string& text);
// The element as XML text (its children and attributes), as a plugin's Load reads it again.
std::string printed(const tinyxml2::XMLElement* e);
}  // namespace xml
}  // namespace bullet_plant

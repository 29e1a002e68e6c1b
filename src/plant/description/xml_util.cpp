#include "description/xml_util.h"

#include <cmath>
#include <sstream>

#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
namespace xml
{
std::string printed(const tinyxml2::XMLElement* e)
{
  tinyxml2::XMLPrinter printer(nullptr, true);
  e->Accept(&printer);
  return printer.CStr();
}

std::string trimmed(const std::string& s)
{
  const char* space = " \t\r\n";
  size_t begin = s.find_first_not_of(space);
  if (begin == std::string::npos)
    return "";
  return s.substr(begin, s.find_last_not_of(space) - begin + 1);
}

const tinyxml2::XMLElement* child(const tinyxml2::XMLElement* e, const std::string& path)
{
  std::stringstream parts(path);
  std::string part;
  while (e && std::getline(parts, part, '/'))
    e = e->FirstChildElement(part.c_str());
  return e;
}

std::string childText(const tinyxml2::XMLElement* e, const std::string& path, const std::string& fallback)
{
  const tinyxml2::XMLElement* c = child(e, path);
  return c && c->GetText() ? trimmed(c->GetText()) : fallback;
}

double childDouble(const tinyxml2::XMLElement* e, const std::string& path, double fallback)
{
  const tinyxml2::XMLElement* c = child(e, path);
  if (!c || !c->GetText())
    return fallback;
  return numbers(c->GetText(), 1, "<" + path + ">")[0];
}

std::vector<double> numbers(const std::string& text, size_t n, const std::string& what)
{
  std::istringstream in(text);
  std::vector<double> values;
  std::string word;
  while (in >> word)
  {
    size_t used = 0;
    double v = 0.0;
    try
    {
      v = std::stod(word, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used != word.size() || !std::isfinite(v))
      throw DescriptionError(what + ": '" + trimmed(text) + "' is not " +
                             (n == 1 ? "a finite number" : std::to_string(n) + " finite numbers"));
    values.push_back(v);
  }
  if (values.size() != n)
    throw DescriptionError(what + ": expected " + std::to_string(n) + " numbers, got '" + trimmed(text) + "'");
  return values;
}

urdf::Pose parseSdfPose(const std::string& text)
{
  urdf::Pose pose;
  if (trimmed(text).empty())
    return pose;
  std::vector<double> v = numbers(text, 6, "<pose>");
  pose.position = urdf::Vector3(v[0], v[1], v[2]);
  pose.rotation.setFromRPY(v[3], v[4], v[5]);
  return pose;
}

}  // namespace xml
}  // namespace bullet_plant

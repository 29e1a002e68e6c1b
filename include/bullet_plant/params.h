// A tree of named values, shaped like the ROS parameter server: the plant reads the same keys
// (NS/gazebo_ros_control/pid_gains/<joint>/p, NS/<controller>/type, ...) from it. The ROS node fills
// it from the parameter server, the Python module from YAML or dicts.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bullet_plant
{
class Param
{
public:
  enum class Type { None, Bool, Int, Double, String, List, Map };

  Param() = default;
  static Param boolean(bool v);
  static Param integer(long long v);
  static Param real(double v);
  static Param string(std::string v);
  static Param list(std::vector<Param> v);
  static Param map();

  Type type() const { return type_; }
  bool isNumber() const { return type_ == Type::Int || type_ == Type::Double; }
  bool isMap() const { return type_ == Type::Map; }

  double asDouble() const;  // Int or Double; throws std::runtime_error otherwise
  bool asBool() const;
  long long asInt() const;
  const std::string& asString() const;
  const std::vector<Param>& asList() const;
  const std::map<std::string, Param>& asMap() const;

  // Child of a map by relative path "a/b/c"; nullptr when any part is missing.
  const Param* find(const std::string& path) const;
  // Sets (creating maps on the way) the value at a path; a leading '/' is ignored.
  void set(const std::string& path, Param value);
  // Merges a map into this one, key by key (as `rosparam load` does).
  void merge(const Param& other);
  bool erase(const std::string& path);

  std::string describe() const;  // short text for error messages, e.g. "'abc'" or "a map"

private:
  Type type_ = Type::None;
  bool bool_ = false;
  long long int_ = 0;
  double double_ = 0.0;
  std::string string_;
  std::vector<Param> list_;
  std::map<std::string, Param> map_;
};

// Normalises a namespace to "/a/b" form ("" and "/" become "").
std::string normaliseNamespace(const std::string& ns);
// Joins a namespace and a relative name: ("/tianracer", "x/p") -> "tianracer/x/p" (a path for Param::find).
std::string joinPath(const std::string& ns, const std::string& name);

}  // namespace bullet_plant

#include "bullet_plant/params.h"

#include <sstream>
#include <stdexcept>

namespace bullet_plant
{
Param Param::boolean(bool v) { Param p; p.type_ = Type::Bool; p.bool_ = v; return p; }
Param Param::integer(long long v) { Param p; p.type_ = Type::Int; p.int_ = v; return p; }
Param Param::real(double v) { Param p; p.type_ = Type::Double; p.double_ = v; return p; }
Param Param::string(std::string v) { Param p; p.type_ = Type::String; p.string_ = std::move(v); return p; }
Param Param::list(std::vector<Param> v) { Param p; p.type_ = Type::List; p.list_ = std::move(v); return p; }
Param Param::map() { Param p; p.type_ = Type::Map; return p; }

double Param::asDouble() const
{
  if (type_ == Type::Double) return double_;
  if (type_ == Type::Int) return static_cast<double>(int_);
  throw std::runtime_error("expected a number, got " + describe());
}

bool Param::asBool() const
{
  if (type_ == Type::Bool) return bool_;
  throw std::runtime_error("expected true or false, got " + describe());
}

long long Param::asInt() const
{
  if (type_ == Type::Int) return int_;
  throw std::runtime_error("expected an integer, got " + describe());
}

const std::string& Param::asString() const
{
  if (type_ == Type::String) return string_;
  throw std::runtime_error("expected a string, got " + describe());
}

const std::vector<Param>& Param::asList() const
{
  if (type_ == Type::List) return list_;
  throw std::runtime_error("expected a list, got " + describe());
}

const std::map<std::string, Param>& Param::asMap() const
{
  if (type_ == Type::Map) return map_;
  throw std::runtime_error("expected a map, got " + describe());
}

namespace
{
std::vector<std::string> splitPath(const std::string& path)
{
  std::vector<std::string> parts;
  std::stringstream in(path);
  std::string part;
  while (std::getline(in, part, '/'))
    if (!part.empty())
      parts.push_back(part);
  return parts;
}
}  // namespace

const Param* Param::find(const std::string& path) const
{
  const Param* p = this;
  for (const std::string& part : splitPath(path))
  {
    if (p->type_ != Type::Map)
      return nullptr;
    auto it = p->map_.find(part);
    if (it == p->map_.end())
      return nullptr;
    p = &it->second;
  }
  return p;
}

void Param::set(const std::string& path, Param value)
{
  Param* p = this;
  for (const std::string& part : splitPath(path))
  {
    if (p->type_ != Type::Map)
      *p = Param::map();
    p = &p->map_[part];
  }
  if (value.type_ == Type::Map && p->type_ == Type::Map)
    p->merge(value);
  else
    *p = std::move(value);
}

void Param::merge(const Param& other)
{
  if (other.type_ != Type::Map || type_ != Type::Map)
  {
    *this = other;
    return;
  }
  for (const auto& kv : other.map_)
  {
    auto it = map_.find(kv.first);
    if (it == map_.end())
      map_[kv.first] = kv.second;
    else
      it->second.merge(kv.second);
  }
}

bool Param::erase(const std::string& path)
{
  std::vector<std::string> parts = splitPath(path);
  if (parts.empty())
    return false;
  Param* p = this;
  for (size_t i = 0; i + 1 < parts.size(); ++i)
  {
    if (p->type_ != Type::Map || !p->map_.count(parts[i]))
      return false;
    p = &p->map_[parts[i]];
  }
  return p->type_ == Type::Map && p->map_.erase(parts.back()) > 0;
}

std::string Param::describe() const
{
  std::ostringstream out;
  switch (type_)
  {
    case Type::None: return "nothing";
    case Type::Bool: return bool_ ? "true" : "false";
    case Type::Int: out << int_; return out.str();
    case Type::Double: out << double_; return out.str();
    case Type::String: return "'" + string_ + "'";
    case Type::List: return "a list";
    case Type::Map: return "a map";
  }
  return "?";
}

std::string normaliseNamespace(const std::string& ns)
{
  std::string out;
  for (const std::string& part : splitPath(ns))
    out += "/" + part;
  return out;
}

std::string joinPath(const std::string& ns, const std::string& name)
{
  std::string joined = normaliseNamespace(normaliseNamespace(ns) + "/" + name);
  return joined.empty() ? joined : joined.substr(1);
}

}  // namespace bullet_plant

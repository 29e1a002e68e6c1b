// How an extension registers itself by name in its own file, as Gazebo's GZ_REGISTER_MODEL_PLUGIN and
// pluginlib's PLUGINLIB_EXPORT_CLASS do: a file defines its class and, beside it, a Registration that
// adds an entry (a factory, or facts about a plugin file) under its names to the one Registry of that
// entry type while the program starts. Nobody keeps a list: what is linked in is registered. The plant
// is a static library, from which the linker takes only the object files something references, and
// nothing references a file that only registers; whoever links the plant links it whole
// (CMakeLists.txt: bullet_plant_whole), and test_registries checks that every name is there.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace bullet_plant
{
// Names -> entries of one type; one registry per entry type.
template <class Entry>
class Registry
{
public:
  // Function-local, so a registration in any file's static initialiser finds it constructed.
  static Registry& instance()
  {
    static Registry registry;
    return registry;
  }

  // A name registered twice is a build mistake (two files claim it): said at start-up, which stops.
  void add(const std::string& name, Entry entry)
  {
    if (!entries_.emplace(name, std::move(entry)).second)
    {
      std::fprintf(stderr, "bullet_plant: '%s' is registered twice; give each registration its own name\n", name.c_str());
      std::abort();
    }
  }

  // The entry of `name`; null when nothing registered it.
  const Entry* find(const std::string& name) const
  {
    auto it = entries_.find(name);
    return it == entries_.end() ? nullptr : &it->second;
  }

  // Every registered name, sorted.
  std::vector<std::string> names() const
  {
    std::vector<std::string> out;
    for (const auto& entry : entries_)
      out.push_back(entry.first);
    return out;
  }

private:
  Registry() = default;
  std::map<std::string, Entry> entries_;  // entries stay put: find's pointers live as long as the program
};

// Registers `entry` under each of `names` when constructed: a static object in the entry's own file.
template <class Entry>
struct Registration
{
  Registration(std::initializer_list<const char*> names, const Entry& entry)
  {
    for (const char* name : names)
      Registry<Entry>::instance().add(name, entry);
  }
};

}  // namespace bullet_plant

// In an extension's .cpp: registers `entry` (of type EntryType) under the names that follow. `id`
// names the registration object, unique in its file. The registering macros of the plugin and
// controller families (GAZEBO_ROS_MODEL_PLUGIN, GAZEBO_ROS_SENSOR_PLUGIN, ROS_CONTROLLER_TYPE) are
// this one with their entry type.
#define BULLET_PLANT_REGISTER(EntryType, id, entry, ...) \
  static const ::bullet_plant::Registration<EntryType> bullet_plant_registration_##id({__VA_ARGS__}, entry)

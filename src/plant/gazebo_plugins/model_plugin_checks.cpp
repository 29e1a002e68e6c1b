// The refusals every model plugin's Load shares: a required element left out, a link name the model
// does not have. Upstream prints "missing, cannot proceed" (or dereferences null) and stops; the plant
// names the element and what to put there, and runs the robot without the plugin.
#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"

namespace bullet_plant
{
bool requireElements(const ModelPluginDescription& d, ModelPluginContext& context,
                     std::initializer_list<const char*> elements, const std::string& purpose)
{
  for (const char* element : elements)
    if (d.text(element, "").empty())
    {
      context.log().error(pluginLabel(d) + " has no <" + element + ">: " + purpose + "; the plugin is not loaded");
      return false;
    }
  return true;
}

bool requireLink(const ModelPluginDescription& d, ModelPluginContext& context, const std::string& element,
                 const std::string& link, const std::string& role)
{
  if (context.robotDescription().model->getLink(link))
    return true;
  context.log().error(pluginLabel(d) + " <" + element + "> names '" + link + "', which is no link of '" +
                      context.modelName() + "'" + (role.empty() ? "" : " (" + role + ")") +
                      "; the plugin is not loaded");
  return false;
}

}  // namespace bullet_plant

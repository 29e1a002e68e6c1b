#include "description/sdf_elements.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <list>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>

#include <sdf/Console.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/parser.hh>
#include <tinyxml2.h>

#include "bullet_plant/log.h"
#include "description/resource_uri.h"
#include "description/xml_util.h"

namespace bullet_plant
{
namespace sdf
{
namespace
{
namespace fs = std::filesystem;

// The plant's own copies of the two models every Gazebo world includes (model://ground_plane,
// model://sun), where this package was built and where it is installed: found before the model path,
// so a world runs the same whether or not Gazebo's model database is installed.
std::vector<std::string> plantModelDirs()
{
  std::vector<std::string> dirs;
  for (const char* dir : {BULLET_PLANT_SOURCE_MODELS, BULLET_PLANT_INSTALLED_MODELS})
  {
    std::error_code ec;
    if (fs::is_directory(dir, ec))
      dirs.push_back(dir);
  }
  return dirs;
}

// What sdformat asks when a URI is none it finds itself: model://NAME[/rest] through the model path
// (GAZEBO_MODEL_PATH and the packages' gazebo_model_path exports), file:// as a path.
std::string findUri(const std::string& uri)
{
  if (uri.rfind("model://", 0) == 0)
  {
    const std::string rest = uri.substr(8);
    const size_t slash = rest.find('/');
    std::string reason;
    const std::string dir = findModelDir(rest.substr(0, slash), reason);
    if (dir.empty() || slash == std::string::npos || slash + 1 == rest.size())
      return dir;
    std::error_code ec;
    const std::string path = dir + rest.substr(slash);
    return fs::exists(path, ec) ? path : "";
  }
  std::error_code ec;
  if (uri.rfind("file://", 0) == 0 && fs::exists(uri.substr(7), ec))
    return uri.substr(7);
  return "";
}

// sdformat reads an included file with its global configuration (parser.cc's readFile), so the
// plant sets that one, once: Gazebo sets its own finder there too.
::sdf::ParserConfig& parserConfig()
{
  static std::once_flag configured;
  std::call_once(configured, [] {
    ::sdf::ParserConfig& config = ::sdf::ParserConfig::GlobalConfig();
    for (const std::string& dir : plantModelDirs())
      config.AddURIPath("model://", dir);
    config.SetFindCallback(findUri);
    // Elements SDF does not define (a plugin's own, a robot maker's extensions) are kept, as Gazebo
    // keeps them, and not reported on the terminal for every document.
    config.SetUnrecognizedElementsPolicy(::sdf::EnforcementPolicy::LOG);
  });
  return ::sdf::ParserConfig::GlobalConfig();
}

// The file an <include><uri> names, as sdformat finds it (a model directory: its model.config's
// SDF file); "" when it finds none.
std::string includedFile(const std::string& uri)
{
  const std::string path = ::sdf::findFile(uri, true, true, parserConfig());
  std::error_code ec;
  if (path.empty() || !fs::is_directory(path, ec))
    return path;
  // (without a config sdformat says so on its console, which is heard only while it reads)
  if (!fs::exists(path + "/model.config", ec) && !fs::exists(path + "/manifest.xml", ec))
    return "";
  return ::sdf::getModelFilePath(path);
}

// sdformat follows <include>s without a limit, so a model that includes itself (through others)
// would recurse until the stack ends: the include graph is walked first, each file once, and a loop
// or nesting deeper than kMaxModelDepth refused, naming the chain. `found`: each include's URI and
// the file it names with its modification time and size ("" where none), which the document's
// reading depends on. What is refused is a Refusal at the document's own <include> that leads to it
// (`top_line`: its line; 0 while walking the document itself).
void checkIncludes(const tinyxml2::XMLElement* e, std::vector<std::string>& chain, std::set<std::string>& checked,
                   std::string& found, int top_line = 0)
{
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
  {
    if (std::string(c->Name()) != "include")
    {
      checkIncludes(c, chain, checked, found, top_line);
      continue;
    }
    const tinyxml2::XMLElement* uri = c->FirstChildElement("uri");
    const std::string uri_text = uri && uri->GetText() ? xml::trimmed(uri->GetText()) : "";
    const int line = top_line ? top_line : c->GetLineNum();
    if (uri_text.empty())  // (sdformat 12 would read a null text)
      throw Refusal("<include> at line " + std::to_string(c->GetLineNum()) + " has no <uri>: name the model it "
                    "includes (model://NAME, or a file or directory)", "include", line);
    const std::string file = includedFile(uri_text);
    found += uri_text + '\n' + file + '\n';
    if (file.empty())
      continue;  // sdformat says so (a warning: the include is skipped)
    std::error_code ec;
    const std::string canonical = fs::weakly_canonical(file, ec).string();
    found += std::to_string(fs::last_write_time(file, ec).time_since_epoch().count()) + ' ' +
             std::to_string(fs::file_size(file, ec)) + '\n';
    auto describe = [&] {
      std::string text;
      for (const std::string& link : chain)
        text += "'" + link + "' -> ";
      return text + "'" + canonical + "'";
    };
    if (std::find(chain.begin(), chain.end(), canonical) != chain.end())
      throw Refusal("an include loop (" + describe() + "): a model cannot include itself; break the loop", "include",
                    line);
    if (chain.size() >= size_t(kMaxModelDepth))
      throw Refusal("models included " + std::to_string(chain.size() + 1) + " deep (" + describe() +
                    "); the plant reads at most " + std::to_string(kMaxModelDepth), "include", line);
    if (!checked.insert(canonical).second)
      continue;
    tinyxml2::XMLDocument doc;
    if (doc.LoadFile(file.c_str()) != tinyxml2::XML_SUCCESS)
      throw Refusal("SDF '" + file + "' (included as '" + uri_text + "') is not well-formed XML: line " +
                    std::to_string(doc.ErrorLineNum()) + ": " + doc.ErrorStr(), "include", line);
    chain.push_back(canonical);
    checkIncludes(doc.RootElement(), chain, checked, found, line);
    chain.pop_back();
  }
}

// A fresh SDF object to read a document into: sdformat's spec files are parsed once. Its root
// <sdf> has attributes of its own and the spec's element descriptions themselves, not copies:
// sdformat reads an element by cloning its description, never changing the description, so a copy
// of the whole spec (7,000 descriptions, 20 ms with sdformat 12.3's Element::Clone; over half of
// reading a small world) is not needed. One document is read at a time (sdformat_mutex).
::sdf::SDFPtr emptyDocument()
{
  static const ::sdf::SDFPtr spec = [] {
    auto sdf = std::make_shared<::sdf::SDF>();
    ::sdf::init(sdf);
    return sdf;
  }();
  const ::sdf::ElementPtr& spec_root = spec->Root();
  auto root = std::make_shared<::sdf::Element>();
  root->SetName(spec_root->GetName());
  root->SetRequired(spec_root->GetRequired());
  for (size_t i = 0; i < spec_root->GetAttributeCount(); ++i)
  {
    const ::sdf::ParamPtr a = spec_root->GetAttribute(i);
    root->AddAttribute(a->GetKey(), a->GetTypeName(), a->GetDefaultAsString(), a->GetRequired(), a->GetDescription());
  }
  for (size_t i = 0; i < spec_root->GetElementDescriptionCount(); ++i)
    root->AddElementDescription(spec_root->GetElementDescription(i));
  auto sdf = std::make_shared<::sdf::SDF>();
  sdf->Root(root);
  return sdf;
}

// What sdformat said (its console's error lines, without colours and source locations), one line.
std::string consoleErrors(const std::string& said)
{
  std::string out;
  std::istringstream lines(said);
  for (std::string line; std::getline(lines, line);)
  {
    std::string plain;
    for (size_t i = 0; i < line.size(); ++i)
      if (line[i] == '\x1b')
        i = line.find('m', i);  // an ANSI colour
      else
        plain += line[i];
    const size_t located = plain.find("] ");
    if (plain.rfind("Error [", 0) != 0 || located == std::string::npos)
      continue;
    const std::string message = xml::trimmed(plain.substr(located + 2));
    if (message.rfind("parse as ", 0) == 0 || out.find(message) != std::string::npos)
      continue;
    out += (out.empty() ? "" : "; ") + message;
  }
  return out;
}

// sdformat's refusal: the innermost element of the document it could not read (sdformat's errors
// run from the innermost out; an error in an included file is named by the <include>'s <uri>),
// named with its named ancestors, its text and line ("model 'm' link 'l' <gravity> 'maybe' (line
// 4)"), and what sdformat said.
Refusal refusal(const std::string& prefix, const tinyxml2::XMLDocument& doc, const ::sdf::Errors& errors,
                const std::string& said)
{
  std::string where, name;
  int line = 0;
  for (const ::sdf::Error& error : errors)
  {
    const std::string message = xml::trimmed(error.Message());
    const std::string reading = "Error reading element <";
    const bool in_document = !error.FilePath() || error.FilePath()->empty() || (*error.FilePath())[0] == '<';
    if (!error.LineNumber() || !in_document)
    {
      if (where.empty() && error.Code() != ::sdf::ErrorCode::ELEMENT_INVALID)
        where = message + (error.FilePath() ? " in '" + *error.FilePath() + "'" : "") +
                (error.LineNumber() ? " (line " + std::to_string(*error.LineNumber()) + ")" : "");
      continue;
    }
    if (message.rfind(reading, 0) == 0)
      name = message.substr(reading.size(), message.find('>') - reading.size());
    else  // named by its XML path's last step: ".../include[0]/uri"
    {
      const std::string path = error.XmlPath() ? *error.XmlPath() : "";
      name = path.substr(path.rfind('/') + 1);
      name = name.substr(0, name.find('['));
    }
    line = *error.LineNumber();
    const tinyxml2::XMLElement* e = elementAt(&doc, name, line);
    std::string element = "<" + name + ">";
    if (e && e->GetText())
      element += " '" + xml::trimmed(e->GetText()) + "'";
    for (const tinyxml2::XMLElement* up = e ? e->Parent()->ToElement() : nullptr; up;
         up = up->Parent() ? up->Parent()->ToElement() : nullptr)
      if (up->Attribute("name"))
        element = std::string(up->Name()) + " '" + up->Attribute("name") + "' " + element;
    where = element + " (line " + std::to_string(line) + ")" +
            (message.rfind(reading, 0) == 0 ? "" : ": " + message);
    break;
  }
  const std::string reason = consoleErrors(said);
  return Refusal(prefix + where + (reason.empty() ? "" : ": " + reason), name, line);
}

// sdformat reports through its console and keeps global state (the parser configuration, the
// console's stream): one document at a time, its messages kept for the refusal.
std::mutex sdformat_mutex;

// The documents read lately, by their text, source and includes (checkIncludes' `found`): a
// document is read again only when one of those changed. sdformat 12.3 spends about 5 ms on each
// model a document holds (Element::Clone re-parses every parameter of the spec it copies), and the
// same document comes again and again: a car spawned many times, a world at each node start. What
// sdformat read is never changed after (the readers read, a plugin's Load gets a copy).
class DocumentCache
{
public:
  bool find(const std::string& key, Document& out)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = entries_.begin(); it != entries_.end(); ++it)
      if (it->first == key)
      {
        out = it->second;
        entries_.splice(entries_.begin(), entries_, it);  // most recent first
        return true;
      }
    return false;
  }
  void add(const std::string& key, const Document& document)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.emplace_front(key, document);
    if (entries_.size() > kEntries)
      entries_.pop_back();
  }

private:
  static constexpr size_t kEntries = 32;
  std::mutex mutex_;
  std::list<std::pair<std::string, Document>> entries_;
};
DocumentCache document_cache;
}  // namespace

const tinyxml2::XMLElement* elementAt(const tinyxml2::XMLNode* e, const std::string& name, int line)
{
  for (const tinyxml2::XMLElement* c = e ? e->FirstChildElement() : nullptr; c; c = c->NextSiblingElement())
  {
    if (c->GetLineNum() == line && name == c->Name())
      return c;
    if (const tinyxml2::XMLElement* found = elementAt(c, name, line))
      return found;
  }
  return nullptr;
}

Document readDocument(const std::string& text, const Source& source)
{
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw DescriptionError("SDF " + source.describe() + " is not well-formed XML: line " +
                           std::to_string(doc.ErrorLineNum()) + ": " + doc.ErrorStr());
  const tinyxml2::XMLElement* root = doc.RootElement();
  const std::string root_name = root ? root->Name() : "";
  // The text as sdformat reads it, line for line: a bare <model> or <world> inside an <sdf> of
  // version 1.6 (an XML declaration before it blanked), an <sdf> without a version given 1.6.
  std::string sdf_text = text;
  if (root_name == "model" || root_name == "world")
  {
    const size_t declaration = sdf_text.find("<?xml"), end = sdf_text.find("?>");
    if (declaration != std::string::npos && end != std::string::npos && end < sdf_text.find('<' + root_name))
      for (size_t i = declaration; i < end + 2; ++i)
        if (sdf_text[i] != '\n')
          sdf_text[i] = ' ';
    sdf_text = "<sdf version=\"1.6\">" + sdf_text + "</sdf>";
  }
  else if (root_name != "sdf")
    throw DescriptionError("SDF " + source.describe() + " has no <sdf> root element (it has <" + root_name + ">)");
  else if (!root->Attribute("version"))
  {
    const size_t open = sdf_text.find("<sdf");
    sdf_text.insert(open + 4, " version=\"1.6\"");
  }
  else if (!std::regex_match(root->Attribute("version"), std::regex("[0-9]+\\.[0-9]+")))
    throw DescriptionError("SDF " + source.describe() + ": <sdf version=\"" + root->Attribute("version") +
                           "\"> is not an SDF version: give one as 1.6 is written (sdformat reads 1.0 to " +
                           ::sdf::SDF::Version() + ")");
  std::vector<std::string> chain;
  if (!source.file.empty())
  {
    std::error_code ec;
    chain.push_back(fs::weakly_canonical(source.file, ec).string());
  }
  std::set<std::string> checked;
  std::string key = source.file + '\n' + source.dir + '\n';
  checkIncludes(doc.RootElement(), chain, checked, key);
  key += sdf_text;
  Document out;
  if (document_cache.find(key, out))
    return out;

  ::sdf::Errors errors;
  std::ostringstream said;
  bool read = false;
  {
    std::lock_guard<std::mutex> lock(sdformat_mutex);
    out.sdf = emptyDocument();
    ::sdf::Console::ConsoleStream& console = ::sdf::Console::Instance()->GetMsgStream();
    std::ostream* terminal = console.GetStream();
    console.SetStream(&said);
    try
    {
      read = ::sdf::readString(sdf_text, parserConfig(), out.sdf->Root(), errors);
    }
    catch (const std::exception& e)  // sdformat's own (a conversion's std::stoi ...)
    {
      said << "Error [sdformat] " << e.what() << "\n";
    }
    console.SetStream(terminal);
  }
  bool refused = !read;
  for (const ::sdf::Error& error : errors)
    if (error.Code() == ::sdf::ErrorCode::URI_LOOKUP)
    {
      std::string looked_in;
      for (const std::string& dir : plantModelDirs())
        looked_in += dir + ", ";
      for (const std::string& dir : modelSearchPath())
        looked_in += dir + ", ";
      const std::string message = xml::trimmed(error.Message());
      const size_t uri = message.find("uri["), end = message.find(']', uri);
      out.warnings.push_back("<include> of '" + (uri == std::string::npos ? "" : message.substr(uri + 4, end - uri - 4)) +
                             "' in " + source.describe() +
                             (error.LineNumber() ? " (line " + std::to_string(*error.LineNumber()) + ")" : "") + ": " +
                             message + "; looked in the plant's models, GAZEBO_MODEL_PATH and the gazebo_model_path exports "
                             "of the packages on ROS_PACKAGE_PATH: " + looked_in.substr(0, looked_in.size() - 2) +
                             "; skipped");
    }
    else
      refused = true;
  if (refused)
    throw refusal("SDF " + source.describe() + ": sdformat cannot read ", doc, errors, said.str());
  document_cache.add(key, out);
  return out;
}

std::string readFile(const std::string& path, const std::string& what)
{
  std::ifstream in(path);
  if (!in)
    throw DescriptionError("cannot read " + what + " '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string directoryOf(const std::string& path) { return fs::absolute(path).parent_path().string(); }

std::string reasonLeftOut(const DescriptionError& refused)
{
  const std::string reason = std::regex_replace(refused.what(), std::regex(" \\(line [0-9]+\\)"), "");
  const size_t said = reason.find("sdformat cannot read");
  return said == std::string::npos ? reason : reason.substr(said);
}

Source sourceOf(const ElementPtr& element, const Source& text)
{
  const std::string& file = element ? element->FilePath() : std::string();
  if (file.empty() || file[0] == '<' || file == text.file)
    return text;
  return Source{file, directoryOf(file)};
}

namespace
{
// An element sdformat added because the spec requires it (with the spec's defaults), not written in
// the document: the plant's readers take it as absent, as they take any element not written (a
// <surface><contact> without <ode> keeps the plant's own contact, not ODE's defaults).
bool addedBySpec(const ElementPtr& e) { return !e->GetExplicitlySetInFile(); }
}  // namespace

ElementPtr child(const ElementPtr& e, const std::string& path)
{
  std::stringstream parts(path);
  ElementPtr found = e;
  for (std::string part; found && std::getline(parts, part, '/');)
  {
    found = found->HasElement(part) ? found->GetElementImpl(part) : ElementPtr();
    if (found && addedBySpec(found))
      found = nullptr;
  }
  return found;
}

std::string text(const ElementPtr& e)
{
  const ::sdf::ParamPtr value = e ? e->GetValue() : ::sdf::ParamPtr();
  return value ? xml::trimmed(value->GetAsString()) : "";
}

std::string childText(const ElementPtr& e, const std::string& path, const std::string& fallback)
{
  const ElementPtr c = child(e, path);
  return c && c->GetValue() ? text(c) : fallback;
}

double childDouble(const ElementPtr& e, const std::string& path, double fallback)
{
  const ElementPtr c = child(e, path);
  const std::string value = c ? text(c) : "";
  if (value.empty())
    return fallback;
  return xml::numbers(value, 1, "<" + path + ">")[0];
}

std::string attribute(const ElementPtr& e, const std::string& name, const std::string& fallback)
{
  const ::sdf::ParamPtr value = e ? e->GetAttribute(name) : ::sdf::ParamPtr();
  return value ? value->GetAsString() : fallback;
}

bool isTrue(const std::string& text) { return text == "true" || text == "1"; }

bool flag(const ElementPtr& parent, const char* tag, bool fallback)
{
  // sdformat has read the spec's booleans (true, false, 1, 0) and refused anything else.
  const ElementPtr e = child(parent, tag);
  return e ? e->Get<bool>() : fallback;
}

urdf::Pose pose(const ElementPtr& e, std::string& relative_to)
{
  const ElementPtr p = child(e, "pose");
  relative_to = attribute(p, "relative_to");
  if (!p)
    return urdf::Pose();
  // SDF 1.9's degrees and quaternions: sdformat's own reading of them.
  if (isTrue(attribute(p, "degrees", "false")) || attribute(p, "rotation_format", "euler_rpy") != "euler_rpy")
  {
    const ignition::math::Pose3d value = p->Get<ignition::math::Pose3d>();
    urdf::Pose out;
    out.position = urdf::Vector3(value.Pos().X(), value.Pos().Y(), value.Pos().Z());
    out.rotation = urdf::Rotation(value.Rot().X(), value.Rot().Y(), value.Rot().Z(), value.Rot().W());
    return out;
  }
  return xml::parseSdfPose(text(p));
}

urdf::Pose pose(const ElementPtr& e)
{
  std::string relative_to;
  return pose(e, relative_to);
}

ElementPtr root(const ElementPtr& e)
{
  ElementPtr up = e;
  while (up && up->GetParent())
    up = up->GetParent();
  return up;
}
namespace
{
bool readMesh(const ElementPtr& mesh, const std::string& where, const Source& source, Shape& shape,
              std::vector<std::string>& warnings, const std::string& left_out)
{
  shape.kind = Shape::Kind::Mesh;
  shape.mesh_uri = childText(mesh, "uri", "");
  std::vector<double> scale = xml::numbers(childText(mesh, "scale", "1 1 1"), 3, where + " <mesh><scale>");
  shape.scale = urdf::Vector3(scale[0], scale[1], scale[2]);
  std::string reason;
  shape.mesh_file = resolveUri(shape.mesh_uri, source.dir, reason);
  if (shape.mesh_file.empty())
    warnings.push_back(where + " in " + source.describe() + ": <mesh> " + reason + "; " + left_out);
  return !shape.mesh_file.empty();
}
}  // namespace

bool readGeometry(const ElementPtr& geometry, const std::string& where, const Source& source, Shape& shape,
                  std::vector<std::string>& warnings, const std::string& left_out)
{
  if (ElementPtr box = child(geometry, "box"))
  {
    shape.kind = Shape::Kind::Box;
    std::vector<double> size = xml::numbers(childText(box, "size", "1 1 1"), 3, where + " <box><size>");
    for (int i = 0; i < 3; ++i)
    {
      if (!(size[i] > 0 && size[i] <= kMaxLength))
        throw DescriptionError(where + ": <box><size> " + childText(box, "size", "") +
                               ": box sizes must be positive and at most " + formatNumber(kMaxLength) + " m");
      shape.box_size[i] = size[i];
    }
  }
  else if (ElementPtr cylinder = child(geometry, "cylinder"))
  {
    shape.kind = Shape::Kind::Cylinder;
    shape.radius = childDouble(cylinder, "radius", 1.0);
    shape.length = childDouble(cylinder, "length", 1.0);
    if (!(shape.radius > 0 && shape.length > 0 && shape.radius <= kMaxLength && shape.length <= kMaxLength))
      throw DescriptionError(where + ": <cylinder> radius " + formatNumber(shape.radius) + " length " +
                             formatNumber(shape.length) + ": both must be positive and at most " +
                             formatNumber(kMaxLength) + " m");
  }
  else if (ElementPtr sphere = child(geometry, "sphere"))
  {
    shape.kind = Shape::Kind::Sphere;
    shape.radius = childDouble(sphere, "radius", 1.0);
    if (!(shape.radius > 0 && shape.radius <= kMaxLength))
      throw DescriptionError(where + ": <sphere><radius> " + formatNumber(shape.radius) +
                             " must be positive and at most " + formatNumber(kMaxLength) + " m");
  }
  else if (ElementPtr capsule = child(geometry, "capsule"))
  {
    // SDF 1.8's (sdformat 11); defaults radius 0.5, length 1.
    shape.kind = Shape::Kind::Capsule;
    auto size = [&](const char* tag, double fallback) {
      const std::string text = childText(capsule, tag, "");
      return text.empty() ? fallback : xml::numbers(text, 1, where + ": <capsule><" + tag + ">")[0];
    };
    shape.radius = size("radius", 0.5);
    shape.length = size("length", 1.0);
    if (!(shape.radius > 0 && shape.length >= 0 && shape.radius <= kMaxLength && shape.length <= kMaxLength))
      throw DescriptionError(where + ": <capsule> radius " + formatNumber(shape.radius) + " length " +
                             formatNumber(shape.length) + ": the radius must be positive, the length at least 0, "
                             "both at most " + formatNumber(kMaxLength) + " m");
  }
  else if (ElementPtr ellipsoid = child(geometry, "ellipsoid"))
  {
    // SDF 1.8's (sdformat 11); default radii 1 1 1.
    shape.kind = Shape::Kind::Ellipsoid;
    const std::string text = childText(ellipsoid, "radii", "1 1 1");
    std::vector<double> radii = xml::numbers(text, 3, where + " <ellipsoid><radii>");
    for (int i = 0; i < 3; ++i)
    {
      if (!(radii[i] > 0 && radii[i] <= kMaxLength))
        throw DescriptionError(where + ": <ellipsoid><radii> " + xml::trimmed(text) +
                               ": each radius must be positive and at most " + formatNumber(kMaxLength) + " m");
      shape.radii[i] = radii[i];
    }
  }
  else if (ElementPtr plane = child(geometry, "plane"))
  {
    shape.kind = Shape::Kind::Plane;
    std::vector<double> n = xml::numbers(childText(plane, "normal", "0 0 1"), 3, where + " <plane><normal>");
    double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(norm >= 1e-9 && std::isfinite(norm)))
      throw DescriptionError(where + ": <plane><normal> must be a finite vector that is not zero");
    shape.normal = urdf::Vector3(n[0] / norm, n[1] / norm, n[2] / norm);
  }
  else if (ElementPtr mesh = child(geometry, "mesh"))
    return readMesh(mesh, where, source, shape, warnings, left_out);
  else
  {
    const ElementPtr first = geometry->GetFirstElement();
    warnings.push_back(where + " in " + source.describe() + ": geometry <" + std::string(first ? first->GetName() : "") +
                       "> is not supported (box, cylinder, sphere, capsule, ellipsoid, plane, mesh); " + left_out);
    return false;
  }
  return true;
}

namespace
{
// gazebo.material's materials that are colours alone (no texture, no shader), as each draws: a
// pass's `ambient`, `diffuse`, `specular r g b [a] shininess` and `emissive`; where a material has
// two passes the second draws over the first (Gazebo/White: OGRE's default white ambient, diffuse
// 1, specular 0.1 at 128). The *Transparent ones' alpha comes from their texture unit's alpha_op;
// RedTransparent is unlit (lighting off): its red is drawn as is.
struct GazeboMaterial
{
  const char* name;
  float ambient[3], diffuse[4], specular[3], shininess, emissive[3];
};
const GazeboMaterial kGazeboMaterials[] = {
    {"Gazebo/Grey", {.3f, .3f, .3f}, {.7f, .7f, .7f, 1}, {.01f, .01f, .01f}, 1.5f, {0, 0, 0}},
    {"Gazebo/DarkGrey", {.175f, .175f, .175f}, {.175f, .175f, .175f, 1}, {.175f, .175f, .175f}, 1.5f, {0, 0, 0}},
    {"Gazebo/White", {1, 1, 1}, {1, 1, 1, 1}, {.1f, .1f, .1f}, 128, {0, 0, 0}},
    {"Gazebo/FlatBlack", {.1f, .1f, .1f}, {.1f, .1f, .1f, 1}, {.01f, .01f, .01f}, 1, {0, 0, 0}},
    {"Gazebo/Black", {0, 0, 0}, {0, 0, 0, 1}, {.1f, .1f, .1f}, 5, {0, 0, 0}},
    {"Gazebo/Red", {1, 0, 0}, {1, 0, 0, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/RedBright", {.87f, .26f, .07f}, {.87f, .26f, .07f, 1}, {.87f, .26f, .07f}, 1, {0, 0, 0}},
    {"Gazebo/Green", {0, 1, 0}, {0, 1, 0, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/Blue", {0, 0, 1}, {0, 0, 1, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/SkyBlue", {.13f, .44f, .70f}, {0, 0, 1, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/Yellow", {1, 1, 0}, {1, 1, 0, 1}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/ZincYellow", {.9725f, .9529f, .2078f}, {.9725f, .9529f, .2078f, 1}, {.9725f, .9529f, .2078f}, 1, {0, 0, 0}},
    {"Gazebo/Purple", {1, 0, 1}, {1, 0, 1, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/Turquoise", {0, 1, 1}, {0, 1, 1, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/Orange", {1, .5088f, .0468f}, {1, .5088f, .0468f, 1}, {.5f, .5f, .5f}, 128, {0, 0, 0}},
    {"Gazebo/Gold", {.4f, .24869f, .020759f}, {.8f, .64869f, .120759f, 1}, {.4f, .4f, .4f}, 12.5f, {0, 0, 0}},
    {"Gazebo/Pioneer2Body", {.481193f, .000123f, .000123f}, {.681193f, .000923f, .000923f, 1}, {.5f, .5f, .5f},
     12.5f, {0, 0, 0}},
    {"Gazebo/GreyTransparent", {.5f, .5f, .5f}, {.5f, .5f, .5f, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/GreenTransparent", {0, 1, 0}, {0, 1, 0, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/BlueTransparent", {0, 0, 1}, {0, 0, 1, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/YellowTransparent", {1, 1, 0}, {1, 1, 0, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/DarkMagentaTransparent", {.6f, 0, .6f}, {.6f, 0, .6f, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/OrangeTransparent", {1, .44f, 0}, {1, .44f, 0, .4f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/RedTransparent", {0, 0, 0}, {0, 0, 0, .5f}, {0, 0, 0}, 0, {1, 0, 0}},
};

Rgba colourOf(const ElementPtr& material, const char* tag, const std::string& where)
{
  const std::string text = childText(material, tag, "");
  std::istringstream words(text);
  size_t count = 0;
  for (std::string word; words >> word;)
    ++count;
  const std::vector<double> c = xml::numbers(text, count == 3 ? 3 : 4, where + " <material><" + tag + ">");
  return {float(c[0]), float(c[1]), float(c[2]), c.size() == 4 ? float(c[3]) : 1.0f};
}
}  // namespace

bool gazeboMaterial(const std::string& name, Material& out)
{
  for (const GazeboMaterial& g : kGazeboMaterials)
    if (name == g.name)
    {
      out.ambient = {g.ambient[0], g.ambient[1], g.ambient[2], 1};
      out.diffuse = {g.diffuse[0], g.diffuse[1], g.diffuse[2], g.diffuse[3]};
      out.specular = {g.specular[0], g.specular[1], g.specular[2], 1};
      out.emissive = {g.emissive[0], g.emissive[1], g.emissive[2], 1};
      out.shininess = g.shininess;
      return true;
    }
  return false;
}

VisualMaterial readMaterial(const ElementPtr& visual, const std::string& where,
                            std::vector<std::string>& warnings)
{
  VisualMaterial out;
  if (!visual)
    return out;
  if (child(visual, "transparency"))
    out.transparency = std::max(0.0, std::min(1.0, childDouble(visual, "transparency", 0.0)));
  const ElementPtr material = child(visual, "material");
  if (!material)
    return out;
  const std::string script = xml::trimmed(childText(material, "script/name", ""));
  if (!script.empty())
  {
    out.has_replace = gazeboMaterial(script, out.replace);
    if (!out.has_replace)
      warnings.push_back(where + ": <material><script> '" + script + "' is not one of gazebo.material's plain "
                         "colours the plant knows (a material script's textures and shaders are not read); the "
                         "visual keeps its own colours");
  }
  struct Given
  {
    const char* tag;
    bool* has;
    Rgba* colour;
  };
  for (const Given& g : {Given{"ambient", &out.has_ambient, &out.ambient}, Given{"diffuse", &out.has_diffuse, &out.diffuse},
                         Given{"specular", &out.has_specular, &out.specular},
                         Given{"emissive", &out.has_emissive, &out.emissive}})
    if (child(material, g.tag))
    {
      *g.has = true;
      *g.colour = colourOf(material, g.tag, where);
    }
  out.shininess = std::max(0.0, childDouble(material, "shininess", 0.0));
  return out;
}

SurfaceDescription readSurface(const ElementPtr& collision, const std::string& where)
{
  SurfaceDescription s;
  const ElementPtr surface = child(collision, "surface");
  if (!surface)
    return s;
  s.given = true;
  s.mu1 = childDouble(surface, "friction/ode/mu", s.mu1);
  s.mu2 = childDouble(surface, "friction/ode/mu2", s.mu2);
  const std::string fdir1 = childText(surface, "friction/ode/fdir1", "");
  if (!fdir1.empty())
  {
    const std::vector<double> d = xml::numbers(fdir1, 3, where + " <surface><friction><ode><fdir1>");
    s.fdir1 = urdf::Vector3(d[0], d[1], d[2]);
  }
  s.slip1 = childDouble(surface, "friction/ode/slip1", s.slip1);
  s.slip2 = childDouble(surface, "friction/ode/slip2", s.slip2);
  s.kp = childDouble(surface, "contact/ode/kp", s.kp);
  s.kd = childDouble(surface, "contact/ode/kd", s.kd);
  s.max_vel = childDouble(surface, "contact/ode/max_vel", s.max_vel);
  s.min_depth = childDouble(surface, "contact/ode/min_depth", s.min_depth);
  s.restitution = childDouble(surface, "bounce/restitution_coefficient", s.restitution);
  s.restitution_threshold = childDouble(surface, "bounce/threshold", s.restitution_threshold);
  return s;
}

}  // namespace sdf
}  // namespace bullet_plant

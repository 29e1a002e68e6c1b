// SDF as the plant reads it, in one place: every world and model document read once by sdformat
// (readDocument: its version conversion, <include>s and defaults are Gazebo's own), then the
// elements a world's static scenery and a simulated model both read from sdformat's tree: where an
// element came from, <geometry>, <material>s (and gazebo.material's plain colours), <surface>, <pose>.
// Private to the plant.
#pragma once

#include <string>
#include <vector>

#include <sdf/Element.hh>
#include <sdf/SDFImpl.hh>
#include <tinyxml2.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
namespace sdf
{
using ElementPtr = ::sdf::ElementPtr;

// Where SDF elements come from: the file messages name, and the directory their relative URIs
// resolve against (the world file's, or the included model's).
struct Source
{
  std::string file;  // "" for SDF given as text
  std::string dir;
  std::string describe() const { return file.empty() ? "the SDF text" : "'" + file + "'"; }
};

// Nested includes deeper than this are refused (sdformat itself follows them without a limit).
constexpr int kMaxModelDepth = 16;

// An SDF document as sdformat reads it: converted to the newest SDF version sdformat knows (so a
// 1.4 joint axis or a 1.6 <pose frame> reads as 1.9 writes it), each <include> replaced by the model
// or light it names (its <name>, <pose>, <static> and <plugin>s applied), elements the spec
// requires added with the spec's defaults. `warnings`: each <include> that was not found (skipped, as
// Gazebo skips one).
struct Document
{
  ::sdf::SDFPtr sdf;
  std::vector<std::string> warnings;
  ElementPtr root() const { return sdf->Root(); }
};

// What sdformat refused in a document: the innermost element of the document itself it could not
// read (its name and line in the text read; "" and 0 where the refusal is not at an element of it).
class Refusal : public DescriptionError
{
public:
  Refusal(const std::string& what, std::string element, int line)
    : DescriptionError(what), element(std::move(element)), line(line)
  {
  }
  std::string element;
  int line;
};

// A refusal's reason for an error about a piece of a document left out: from "sdformat cannot read"
// on (the whole message where it has none), without the line numbers, which are those of the text
// sdformat read (a document printed again), not of what the user wrote.
std::string reasonLeftOut(const DescriptionError& refused);

// Reads the SDF text `text` (`source`: where it came from). A bare <model> or <world>, or an <sdf>
// without a version, is read as SDF 1.6 (gazebo_ros's spawn_model sends such). model:// URIs are
// found through the model path (resource_uri.h), the plant's own ground_plane and sun first.
// Throws DescriptionError for XML that is not well-formed, an include loop or nesting deeper than
// kMaxModelDepth; Refusal for what sdformat refuses.
Document readDocument(const std::string& text, const Source& source);
std::string readFile(const std::string& path, const std::string& what);
std::string directoryOf(const std::string& path);

// The element named `name` at `line` below `e` (a document or an element) in XML as tinyxml2 read
// it, the first in document order; null for none. sdformat's errors name elements so.
const tinyxml2::XMLElement* elementAt(const tinyxml2::XMLNode* e, const std::string& name, int line);

// The Source of `element`: the file sdformat read it from (an included model's file), else `text`,
// the document's own.
Source sourceOf(const ElementPtr& element, const Source& text);

// --- Reading sdformat's elements. Each takes a null element as one that is not there. ---

// The first child element along the relative path "a/b"; null when one is missing.
ElementPtr child(const ElementPtr& e, const std::string& path);
// The element's value as written (trimmed), or the spec's default where it was not written; "" for
// an element without a value.
std::string text(const ElementPtr& e);
std::string childText(const ElementPtr& e, const std::string& path, const std::string& fallback);
// A number child; throws DescriptionError naming the element when its text is not a finite number.
double childDouble(const ElementPtr& e, const std::string& path, double fallback);
// The attribute `name` as written, or the spec's default; `fallback` where the element has none.
std::string attribute(const ElementPtr& e, const std::string& name, const std::string& fallback = "");
bool isTrue(const std::string& text);
// A boolean child element of the spec's, as sdformat read it; `fallback` without the element.
bool flag(const ElementPtr& parent, const char* tag, bool fallback);
// `e`'s <pose> (identity where it has none) and the frame it is relative_to ("" when not given).
urdf::Pose pose(const ElementPtr& e, std::string& relative_to);
urdf::Pose pose(const ElementPtr& e);
// The root of the document `e` is in (its elements hold their parents weakly).
ElementPtr root(const ElementPtr& e);

// The shape of a <geometry> (box, cylinder, sphere, plane, mesh with its <scale>, and SDF 1.8's capsule
// and ellipsoid); false with a
// warning ending in `left_out` for a geometry the plant does not have or a mesh not found. Throws
// DescriptionError for a size that is not positive.
bool readGeometry(const ElementPtr& geometry, const std::string& where, const Source& source, Shape& shape,
                  std::vector<std::string>& warnings, const std::string& left_out = "collision left out");

// A <visual>'s <material> and <transparency> (VisualMaterial): its colours, <shininess>, and a
// <script> naming one of gazebo.material's plain materials (gazeboMaterial). A script the plant does
// not know (its own file's, or a textured Gazebo/* one) is said in `warnings` and left out. Throws
// DescriptionError naming `where` for a colour that is not three or four numbers.
VisualMaterial readMaterial(const ElementPtr& visual, const std::string& where, std::vector<std::string>& warnings);
// The material of a Gazebo/* script (media/materials/scripts/gazebo.material) that is colours
// alone: false for a name that is not one of them.
bool gazeboMaterial(const std::string& name, Material& out);

// A <collision>'s <surface>: friction (ode mu, mu2, fdir1, slip1, slip2), bounce and contact (ode
// kp, kd, max_vel, min_depth), SDF's defaults where absent (the contact's: negative, not given).
// Throws DescriptionError naming `where` for an fdir1 that is not three numbers.
SurfaceDescription readSurface(const ElementPtr& collision, const std::string& where);

}  // namespace sdf
}  // namespace bullet_plant

#include "bullet_plant/sdf_model.h"

namespace bullet_plant
{
namespace sdf
{
// A <model> element read as the plant simulates it (sdf_model.cpp): what parseSdfModel gives, for the
// world's reader too. `source`: the document's.
ModelDescription readModel(const ElementPtr& model, const Source& source);
}  // namespace sdf
}  // namespace bullet_plant

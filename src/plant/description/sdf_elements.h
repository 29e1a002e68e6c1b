// The SDF elements a world's static scenery and a simulated model both read, in one place: where an
// element came from, <geometry>, <material>s (and gazebo.material's plain colours), <surface>, 1.7's <pose relative_to>, and
// finding the file of an <include>d model. Private to the plant.
#pragma once

#include <string>
#include <vector>

#include <tinyxml2.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
namespace sdf
{
// Where SDF elements come from: the file messages name, and the directory their relative URIs
// resolve against (the world file's, or the included model's).
struct Source
{
  std::string file;  // "" for SDF given as text
  std::string dir;
  std::string describe() const { return file.empty() ? "the SDF text" : "'" + file + "'"; }
  // The model files whose <include>s led here, outermost first: an include of one of them (or of
  // `file`) is a loop.
  std::vector<std::string> includers;
};

// Nested includes deeper than this are a loop (a model including itself).
constexpr int kMaxModelDepth = 16;

// Throws DescriptionError with the line for XML that is not well-formed.
void parseXml(tinyxml2::XMLDocument& doc, const std::string& text, const Source& source);
std::string readFile(const std::string& path, const std::string& what);
std::string directoryOf(const std::string& path);
bool isTrue(const std::string& text);
// A boolean child element as sdformat reads one (true, false, 1, 0, any case; `fallback` without the
// element). Throws DescriptionError naming `where`, the element and its text for anything else.
bool readFlag(const tinyxml2::XMLElement* parent, const char* tag, bool fallback, const std::string& where);

// The shape of a <geometry> (box, cylinder, sphere, plane, mesh with its <scale>, and SDF 1.8's capsule
// and ellipsoid); false with a
// warning ending in `left_out` for a geometry the plant does not have or a mesh not found. Throws
// DescriptionError for a size that is not positive.
bool readGeometry(const tinyxml2::XMLElement* geometry, const std::string& where, const Source& source, Shape& shape,
                  std::vector<std::string>& warnings, const std::string& left_out = "collision left out");

// A <visual>'s <material> and <transparency> (VisualMaterial): its colours, <shininess>, and a
// <script> naming one of gazebo.material's plain materials (gazeboMaterial). A script the plant does
// not know (its own file's, or a textured Gazebo/* one) is said in `warnings` and left out. Throws
// DescriptionError naming `where` for a colour that is not three or four numbers.
VisualMaterial readMaterial(const tinyxml2::XMLElement* visual, const std::string& where,
                            std::vector<std::string>& warnings);
// The material of a Gazebo/* script (media/materials/scripts/gazebo.material) that is colours
// alone: false for a name that is not one of them.
bool gazeboMaterial(const std::string& name, Material& out);

// A <collision>'s <surface>: friction (ode mu, mu2, fdir1), bounce and contact (ode kp, kd, max_vel,
// min_depth), SDF's defaults where absent (the contact's: negative, not given). Throws
// DescriptionError naming `where` for an fdir1 that is not three numbers.
SurfaceDescription readSurface(const tinyxml2::XMLElement* collision, const std::string& where);

// The model file model.config names: the <sdf> of the newest version; model.sdf without a config.
std::string modelFile(const std::string& model_dir);
// The directory an <include><uri> names: model://NAME through the model path, or a path (relative to
// the including file's directory); "" with `reason` when there is none.
std::string includedModelDir(const std::string& uri, const Source& source, std::string& reason);

// The Source of the model file `model_file` in `model_dir` included from `from`; "" in `loop` unless
// that file is `from`'s own or one of its includers' (an include loop: the chain, "a -> b -> a").
Source includedSource(const std::string& model_file, const std::string& model_dir, const Source& from,
                      std::string& loop);

// An <include>'s model, found as Gazebo finds it (includedModelDir, modelFile) and read into `doc`:
// its <model> element, `model_source` saying where it came from; null with `why` when there is none
// to read (nested deeper than kMaxModelDepth, not found, an include loop, no <sdf><model> in the
// file). Throws DescriptionError for a file that is not well-formed XML.
const tinyxml2::XMLElement* readIncludedModel(const std::string& uri, const Source& from, int depth,
                                              tinyxml2::XMLDocument& doc, Source& model_source, std::string& why);

// The <sdf version="..."> of the document holding `element`, as major * 100 + minor (1.6 -> 106);
// 106 when not given.
int versionOf(const tinyxml2::XMLElement* element);

}  // namespace sdf
}  // namespace bullet_plant

#include "bullet_plant/sdf_model.h"

namespace bullet_plant
{
namespace sdf
{
// A <model> element read as the plant simulates it (sdf_model.cpp): what parseSdfModel gives, for the
// world's reader too. `depth`: how deep in includes it is.
ModelDescription readModel(const tinyxml2::XMLElement* model, const Source& source, int depth = 0);
}  // namespace sdf
}  // namespace bullet_plant

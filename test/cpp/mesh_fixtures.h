// Small mesh files written by the tests themselves into a fresh temporary directory.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace mesh_fixtures
{
// A fresh directory named prefix_XXXXXX under $TMPDIR (test_gtests.py gives each case its pytest
// tmp_path, which pytest cleans up), else under /tmp.
inline std::string tempDir(const std::string& prefix = "plant_meshes")
{
  const char* base = std::getenv("TMPDIR");
  std::string pattern = std::string(base && *base ? base : "/tmp") + "/" + prefix + "_XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const char* dir = mkdtemp(buffer.data());
  return dir ? dir : "/tmp";
}

inline std::string write(const std::string& dir, const std::string& name, const std::string& text)
{
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A box from corner lo to corner hi as a binary STL (12 triangles, outward winding).
inline std::string binaryBoxStl(const std::string& dir, const std::string& name, const float lo[3], const float hi[3])
{
  float corners[8][3];
  for (int c = 0; c < 8; ++c)
    for (int i = 0; i < 3; ++i)
      corners[c][i] = (c >> (2 - i)) & 1 ? hi[i] : lo[i];
  const int faces[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                            {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  std::string bytes(80, '\0');
  const uint32_t count = 12;
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& face : faces)
  {
    const float normal[3] = {0, 0, 0};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    for (int k : face)
      bytes.append(reinterpret_cast<const char*>(corners[k]), 12);
    bytes.append(2, '\0');
  }
  return write(dir, name, bytes);
}

// One triangle in a Collada file with the given <unit meter> and <up_axis>, its material's effect
// the given technique (its shading element and what it holds), and texture coordinates.
inline std::string colladaTriangleOf(const std::string& dir, const std::string& name, const std::string& meter,
                                     const std::string& up_axis, const std::string& positions,
                                     const std::string& technique, const std::string& images = "")
{
  return write(dir, name,
               "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
               "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
               "  <asset><unit name=\"u\" meter=\"" + meter + "\"/><up_axis>" + up_axis + "</up_axis></asset>\n"
               "  <library_images>" + images + "</library_images>\n"
               "  <library_effects><effect id=\"fx\"><profile_COMMON>"
               "<newparam sid=\"surface\"><surface type=\"2D\"><init_from>picture</init_from></surface></newparam>"
               "<newparam sid=\"sampler\"><sampler2D><source>surface</source></sampler2D></newparam>"
               "<technique sid=\"common\">" + technique + "</technique></profile_COMMON></effect>"
               "</library_effects>\n"
               "  <library_materials><material id=\"paint-id\" name=\"paint\"><instance_effect url=\"#fx\"/></material>"
               "</library_materials>\n"
               "  <library_geometries><geometry id=\"tri\" name=\"tri\"><mesh>\n"
               "    <source id=\"pos\"><float_array id=\"pos-array\" count=\"9\">" + positions + "</float_array>\n"
               "      <technique_common><accessor source=\"#pos-array\" count=\"3\" stride=\"3\">"
               "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>"
               "</accessor></technique_common></source>\n"
               "    <source id=\"uv\"><float_array id=\"uv-array\" count=\"6\">0 0 1 0 0 1</float_array>\n"
               "      <technique_common><accessor source=\"#uv-array\" count=\"3\" stride=\"2\">"
               "<param name=\"S\" type=\"float\"/><param name=\"T\" type=\"float\"/>"
               "</accessor></technique_common></source>\n"
               "    <vertices id=\"vtx\"><input semantic=\"POSITION\" source=\"#pos\"/></vertices>\n"
               "    <triangles material=\"mat\" count=\"1\"><input semantic=\"VERTEX\" source=\"#vtx\" offset=\"0\"/>"
               "<input semantic=\"TEXCOORD\" source=\"#uv\" offset=\"0\" set=\"0\"/><p>0 1 2</p></triangles>\n"
               "  </mesh></geometry></library_geometries>\n"
               "  <library_visual_scenes><visual_scene id=\"scene\"><node id=\"n\" name=\"n\">"
               "<instance_geometry url=\"#tri\"><bind_material><technique_common>"
               "<instance_material symbol=\"mat\" target=\"#paint-id\"><bind_vertex_input semantic=\"UVMap\" "
               "input_semantic=\"TEXCOORD\" input_set=\"0\"/></instance_material></technique_common></bind_material>"
               "</instance_geometry></node></visual_scene></library_visual_scenes>\n"
               "  <scene><instance_visual_scene url=\"#scene\"/></scene>\n"
               "</COLLADA>\n");
}

// One triangle in a Collada file with the given <unit meter> and <up_axis>, coloured by a lambert
// material with the given diffuse colour.
inline std::string colladaTriangle(const std::string& dir, const std::string& name, const std::string& meter,
                                   const std::string& up_axis, const std::string& positions,
                                   const std::string& diffuse = "1 0 0 1")
{
  return write(dir, name,
               "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
               "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
               "  <asset><unit name=\"u\" meter=\"" + meter + "\"/><up_axis>" + up_axis + "</up_axis></asset>\n"
               "  <library_effects><effect id=\"fx\"><profile_COMMON><technique sid=\"common\"><lambert>"
               "<diffuse><color>" + diffuse + "</color></diffuse></lambert></technique></profile_COMMON></effect>"
               "</library_effects>\n"
               "  <library_materials><material id=\"paint\" name=\"paint\"><instance_effect url=\"#fx\"/></material>"
               "</library_materials>\n"
               "  <library_geometries><geometry id=\"tri\" name=\"tri\"><mesh>\n"
               "    <source id=\"pos\"><float_array id=\"pos-array\" count=\"9\">" + positions + "</float_array>\n"
               "      <technique_common><accessor source=\"#pos-array\" count=\"3\" stride=\"3\">"
               "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>"
               "</accessor></technique_common></source>\n"
               "    <vertices id=\"vtx\"><input semantic=\"POSITION\" source=\"#pos\"/></vertices>\n"
               "    <triangles material=\"mat\" count=\"1\"><input semantic=\"VERTEX\" source=\"#vtx\" offset=\"0\"/>"
               "<p>0 1 2</p></triangles>\n"
               "  </mesh></geometry></library_geometries>\n"
               "  <library_visual_scenes><visual_scene id=\"scene\"><node id=\"n\" name=\"n\">"
               "<instance_geometry url=\"#tri\"><bind_material><technique_common>"
               "<instance_material symbol=\"mat\" target=\"#paint\"/></technique_common></bind_material>"
               "</instance_geometry></node></visual_scene></library_visual_scenes>\n"
               "  <scene><instance_visual_scene url=\"#scene\"/></scene>\n"
               "</COLLADA>\n");
}

// A wheel: an n-sided prism of circumradius r about the y axis, from y = -w/2 to w/2, as an OBJ.
inline std::string wheelObj(const std::string& dir, const std::string& name, double r, double w, int n)
{
  std::string obj;
  for (int k = 0; k < n; ++k)
    for (double y : {-w / 2, w / 2})
      obj += "v " + std::to_string(r * std::cos(2 * M_PI * k / n)) + " " + std::to_string(y) + " " +
             std::to_string(r * std::sin(2 * M_PI * k / n)) + "\n";
  for (int k = 0; k < n; ++k)
  {
    const int a = 2 * k + 1, b = 2 * ((k + 1) % n) + 1;  // the rim's quad k
    obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(b + 1) + "\n";
    obj += "f " + std::to_string(a) + " " + std::to_string(b + 1) + " " + std::to_string(a + 1) + "\n";
    if (k >= 1 && k + 1 < n)  // the two sides as fans
    {
      obj += "f 1 " + std::to_string(b) + " " + std::to_string(a) + "\n";
      obj += "f 2 " + std::to_string(a + 1) + " " + std::to_string(b + 1) + "\n";
    }
  }
  return write(dir, name, obj);
}

}  // namespace mesh_fixtures

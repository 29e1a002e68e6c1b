// resource_uri.cpp: every URI form Gazebo and ROS users write, resolved in a directory tree made
// for each test, with only the environment (GAZEBO_MODEL_PATH, ROS_PACKAGE_PATH) to go by.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "description/resource_uri.h"

using namespace bullet_plant;
namespace fs = std::filesystem;

namespace
{
class ResourceUri : public ::testing::Test
{
protected:
  void SetUp() override
  {
    char pattern[] = "/tmp/test_resource_uri_XXXXXX";
    root = mkdtemp(pattern);
    // GAZEBO_MODEL_PATH models
    write("models/crate/model.config", "<model><name>crate</name></model>");
    write("models/crate/meshes/crate.stl", "solid crate\nendsolid crate\n");
    write("models/shared/meshes/from_model_path.stl", "solid a\nendsolid a\n");
    // a workspace with a package whose directory is not its name, exporting a model path
    write("ws/src/group/pkg_dir/package.xml",
          "<package format=\"2\"><name>my_worlds</name><export>"
          "<gazebo_ros gazebo_model_path=\"${prefix}/models:${prefix}/more_models\" gazebo_media_path=\"${prefix}\"/>"
          "</export></package>");
    write("ws/src/group/pkg_dir/worlds/shipped.world", "<sdf/>");
    write("media/worlds/shipped.world", "<sdf/>");
    write("ws/src/group/pkg_dir/meshes/part.dae", "<COLLADA/>");
    write("ws/src/group/pkg_dir/models/exported/meshes/e.stl", "solid e\nendsolid e\n");
    write("ws/src/group/pkg_dir/more_models/shared/meshes/from_export.stl", "solid b\nendsolid b\n");
    write("ws/src/ignored/CATKIN_IGNORE", "");
    write("ws/src/ignored/hidden_pkg/package.xml", "<package><name>hidden_pkg</name></package>");
    // a world with a mesh next to it
    write("world/meshes/rock.obj", "v 0 0 0\n");
    setenv("GAZEBO_MODEL_PATH", (root + "/nowhere:" + root + "/models").c_str(), 1);
    setenv("ROS_PACKAGE_PATH", (root + "/ws/src").c_str(), 1);
  }
  void TearDown() override { fs::remove_all(root); }

  void write(const std::string& relative, const std::string& text)
  {
    fs::path path = fs::path(root) / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
  }

  std::string resolved(const std::string& uri, const std::string& base_dir = "")
  {
    std::string reason;
    std::string path = resolveUri(uri, base_dir, reason);
    EXPECT_FALSE(path.empty()) << uri << ": " << reason;
    return path.empty() ? "" : fs::canonical(path).string();
  }

  std::string reasonFor(const std::string& uri, const std::string& base_dir = "")
  {
    std::string reason;
    EXPECT_EQ(resolveUri(uri, base_dir, reason), "") << uri;
    return reason;
  }

  std::string real(const std::string& relative) { return fs::canonical(fs::path(root) / relative).string(); }

  std::string root;
};
}  // namespace

TEST_F(ResourceUri, ModelUriThroughGazeboModelPath)
{
  EXPECT_EQ(resolved("model://crate/meshes/crate.stl"), real("models/crate/meshes/crate.stl"));
}

TEST_F(ResourceUri, ModelUriThroughAPackagesGazeboModelPathExport)
{
  EXPECT_EQ(resolved("model://exported/meshes/e.stl"), real("ws/src/group/pkg_dir/models/exported/meshes/e.stl"));
}

TEST_F(ResourceUri, GazeboModelPathComesBeforeExports)
{
  write("ws/src/group/pkg_dir/more_models/shared/meshes/from_model_path.stl", "solid c\nendsolid c\n");
  EXPECT_EQ(resolved("model://shared/meshes/from_model_path.stl"), real("models/shared/meshes/from_model_path.stl"));
  // Gazebo looks for the whole NAME/rest in each directory in turn, not for the first NAME.
  EXPECT_EQ(resolved("model://shared/meshes/from_export.stl"),
            real("ws/src/group/pkg_dir/more_models/shared/meshes/from_export.stl"));
  std::string reason;
  EXPECT_EQ(fs::canonical(findModelDir("shared", reason)).string(), real("models/shared"));
}

TEST_F(ResourceUri, MissingModelNamesEverywhereItLooked)
{
  std::string reason = reasonFor("model://no_such_model/meshes/a.stl");
  EXPECT_NE(reason.find("model://no_such_model/meshes/a.stl"), std::string::npos) << reason;
  EXPECT_NE(reason.find("GAZEBO_MODEL_PATH"), std::string::npos) << reason;
  EXPECT_NE(reason.find(root + "/nowhere"), std::string::npos) << reason;
  EXPECT_NE(reason.find(root + "/ws/src/group/pkg_dir/more_models"), std::string::npos) << reason;
}

TEST_F(ResourceUri, FindModelDirGivesTheModelsDirectory)
{
  std::string reason;
  EXPECT_EQ(fs::canonical(findModelDir("crate", reason)).string(), real("models/crate"));
  EXPECT_EQ(findModelDir("hidden_pkg", reason), "");
  EXPECT_NE(reason.find("'hidden_pkg'"), std::string::npos) << reason;
}

TEST_F(ResourceUri, PackageUriByPackageNameNotDirectoryName)
{
  EXPECT_EQ(resolved("package://my_worlds/meshes/part.dae"), real("ws/src/group/pkg_dir/meshes/part.dae"));
  std::string reason = reasonFor("package://pkg_dir/meshes/part.dae");
  EXPECT_NE(reason.find("not on ROS_PACKAGE_PATH"), std::string::npos) << reason;
  EXPECT_NE(reason.find(root + "/ws/src"), std::string::npos) << reason;
}

TEST_F(ResourceUri, PackagesUnderCatkinIgnoreAreNotFound)
{
  EXPECT_NE(reasonFor("package://hidden_pkg/package.xml").find("not on ROS_PACKAGE_PATH"), std::string::npos);
}

TEST_F(ResourceUri, PackageFileMissingNamesThePathLookedAt)
{
  std::string reason = reasonFor("package://my_worlds/meshes/none.dae");
  EXPECT_NE(reason.find("pkg_dir/meshes/none.dae"), std::string::npos) << reason;
}

TEST_F(ResourceUri, FileUriAndAbsolutePath)
{
  const std::string path = root + "/world/meshes/rock.obj";
  EXPECT_EQ(resolved("file://" + path), real("world/meshes/rock.obj"));
  EXPECT_EQ(resolved(path, "/somewhere/else"), real("world/meshes/rock.obj"));
}

TEST_F(ResourceUri, RelativePathsResolveAgainstTheNamingFilesDirectory)
{
  EXPECT_EQ(resolved("meshes/rock.obj", root + "/world"), real("world/meshes/rock.obj"));
  EXPECT_EQ(resolved("file://meshes/rock.obj", root + "/world"), real("world/meshes/rock.obj"));
  std::string reason = reasonFor("meshes/rock.obj", root + "/models");
  EXPECT_NE(reason.find(root + "/models/meshes/rock.obj"), std::string::npos) << reason;
}

TEST_F(ResourceUri, ADirectoryIsNotAFile)
{
  EXPECT_NE(reasonFor("model://crate/meshes").find("looked in"), std::string::npos);
  EXPECT_NE(reasonFor(root + "/world/meshes").find("not found"), std::string::npos);
}

TEST_F(ResourceUri, WorldFileAsGivenThenResourcePathThenMediaPathExports)
{
  std::string reason;
  EXPECT_EQ(findWorldFile(root + "/world/meshes/rock.obj", reason), root + "/world/meshes/rock.obj");
  EXPECT_EQ(findWorldFile("worlds/shipped.world", reason), root + "/ws/src/group/pkg_dir/worlds/shipped.world");
  setenv("GAZEBO_RESOURCE_PATH", (root + "/media").c_str(), 1);
  EXPECT_EQ(findWorldFile("worlds/shipped.world", reason), root + "/media/worlds/shipped.world");
  unsetenv("GAZEBO_RESOURCE_PATH");
  EXPECT_EQ(findWorldFile("worlds/none.world", reason), "");
  EXPECT_NE(reason.find("'worlds/none.world'"), std::string::npos) << reason;
  EXPECT_NE(reason.find(root + "/ws/src/group/pkg_dir"), std::string::npos) << reason;
}

// Worlds shipped as packages (AWS RoboMaker's) name their meshes file://models/NAME/meshes/...,
// relative to the package that exports itself as gazebo_media_path: Gazebo's FindFile looks in
// the working directory, then GAZEBO_RESOURCE_PATH (where gazebo_ros puts the exports).
TEST_F(ResourceUri, RelativeFileUriNotBesideItsFileIsLookedForInTheResourcePath)
{
  const std::string model_dir = root + "/ws/src/group/pkg_dir/models/exported";
  EXPECT_EQ(resolved("file://models/exported/meshes/e.stl", model_dir),
            real("ws/src/group/pkg_dir/models/exported/meshes/e.stl"));
  write("media/models/exported/meshes/e.stl", "solid m\nendsolid m\n");
  setenv("GAZEBO_RESOURCE_PATH", (root + "/media").c_str(), 1);
  EXPECT_EQ(resolved("file://models/exported/meshes/e.stl", model_dir), real("media/models/exported/meshes/e.stl"));
  unsetenv("GAZEBO_RESOURCE_PATH");
  const std::string reason = reasonFor("file://models/exported/meshes/none.stl", model_dir);
  EXPECT_NE(reason.find(model_dir + "/models/exported/meshes/none.stl"), std::string::npos) << reason;
  EXPECT_NE(reason.find("GAZEBO_RESOURCE_PATH"), std::string::npos) << reason;
  EXPECT_NE(reason.find(root + "/ws/src/group/pkg_dir"), std::string::npos) << reason;
}

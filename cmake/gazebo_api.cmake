# Gazebo 11's C++ API for users' plugins (include/gazebo-11/, src/gazebo/), and Gazebo's
# development files as users' packages find them: find_package(gazebo) (gazebo-config.cmake in
# share/gazebo/cmake of the devel and install spaces) and `pkg-config gazebo` (lib/pkgconfig);
# compat/gazebo_dev is catkin's gazebo_dev over them. Included by CMakeLists.txt.
find_package(sdformat12 REQUIRED)
find_package(ignition-math6 REQUIRED)
find_package(Boost REQUIRED)

set(GAZEBO_API_VERSION_FULL 11.15.1)  # include/gazebo-11/gazebo/gazebo_config.h says the same
set(GAZEBO_API_VERSION 11.15)
set(GAZEBO_API_MAJOR_VERSION 11)

# Gazebo's common library: time, the console, events, plugin paths, animations.
add_library(gazebo_common SHARED
  src/gazebo/common/Animation.cc
  src/gazebo/common/Console.cc
  src/gazebo/common/Events.cc
  src/gazebo/common/Exception.cc
  src/gazebo/common/KeyFrame.cc
  src/gazebo/common/PID.cc
  src/gazebo/common/SystemPaths.cc
  src/gazebo/common/Time.cc)
target_include_directories(gazebo_common PUBLIC
  include/gazebo-11 ${Boost_INCLUDE_DIRS})
target_compile_options(gazebo_common PRIVATE -Wall -Wextra)
target_link_libraries(gazebo_common PUBLIC sdformat12::sdformat12 ignition-math6::ignition-math6 ${CMAKE_DL_LIBS})
set_target_properties(gazebo_common PROPERTIES
  LIBRARY_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_LIB_DESTINATION}
  VERSION ${GAZEBO_API_VERSION_FULL} SOVERSION ${GAZEBO_API_MAJOR_VERSION})
# Gazebo's physics classes for plugins (World, Model, Link, Joint) over the simulator's bridge
# (gazebo/physics/PlantBridge.hh), which the plant implements.
add_library(gazebo_physics SHARED
  src/gazebo/physics/Joint.cc
  src/gazebo/physics/JointController.cc
  src/gazebo/physics/Link.cc
  src/gazebo/physics/Model.cc
  src/gazebo/physics/PhysicsEngine.cc
  src/gazebo/physics/World.cc)
target_compile_options(gazebo_physics PRIVATE -Wall -Wextra)
target_link_libraries(gazebo_physics PUBLIC gazebo_common)
set_target_properties(gazebo_physics PROPERTIES
  LIBRARY_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_LIB_DESTINATION}
  VERSION ${GAZEBO_API_VERSION_FULL} SOVERSION ${GAZEBO_API_MAJOR_VERSION})
# Gazebo's sensors library: the Sensor base class (the plant's sensors as Gazebo's: issue 55's).
add_library(gazebo_sensors SHARED
  src/gazebo/sensors/Sensor.cc)
target_compile_options(gazebo_sensors PRIVATE -Wall -Wextra)
target_link_libraries(gazebo_sensors PUBLIC gazebo_physics gazebo_common)
set_target_properties(gazebo_sensors PROPERTIES
  LIBRARY_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_LIB_DESTINATION}
  VERSION ${GAZEBO_API_VERSION_FULL} SOVERSION ${GAZEBO_API_MAJOR_VERSION})
set(GAZEBO_API_LIBRARIES gazebo_sensors gazebo_physics gazebo_common)
list(TRANSFORM GAZEBO_API_LIBRARIES PREPEND -l OUTPUT_VARIABLE GAZEBO_API_PKG_LIBS)
list(JOIN GAZEBO_API_PKG_LIBS " " GAZEBO_API_PKG_LIBS)

install(TARGETS ${GAZEBO_API_LIBRARIES} LIBRARY DESTINATION ${CATKIN_GLOBAL_LIB_DESTINATION})
install(DIRECTORY include/gazebo-11/ DESTINATION ${CATKIN_GLOBAL_INCLUDE_DESTINATION}/gazebo-11)

# The config and pkg-config files, once for each space: its include folder and its lib folder.
foreach(space devel install)
  if(space STREQUAL devel)
    set(GAZEBO_API_PREFIX ${CATKIN_DEVEL_PREFIX})
    set(GAZEBO_API_INCLUDE_DIR ${PROJECT_SOURCE_DIR}/include/gazebo-11)
  else()
    set(GAZEBO_API_PREFIX ${CMAKE_INSTALL_PREFIX})
    set(GAZEBO_API_INCLUDE_DIR ${CMAKE_INSTALL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION}/gazebo-11)
  endif()
  set(GAZEBO_API_LIB_DIR ${GAZEBO_API_PREFIX}/${CATKIN_GLOBAL_LIB_DESTINATION})
  set(out ${CMAKE_CURRENT_BINARY_DIR}/gazebo_api_${space})
  configure_file(cmake/gazebo-config.cmake.in ${out}/gazebo-config.cmake @ONLY)
  configure_file(cmake/gazebo.pc.in ${out}/gazebo.pc @ONLY)
  include(CMakePackageConfigHelpers)
  write_basic_package_version_file(${out}/gazebo-config-version.cmake VERSION ${GAZEBO_API_VERSION_FULL}
    COMPATIBILITY AnyNewerVersion)
  if(space STREQUAL devel)
    file(COPY ${out}/gazebo-config.cmake ${out}/gazebo-config-version.cmake
      DESTINATION ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_SHARE_DESTINATION}/gazebo/cmake)
    file(COPY ${out}/gazebo.pc DESTINATION ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_LIB_DESTINATION}/pkgconfig)
  else()
    install(FILES ${out}/gazebo-config.cmake ${out}/gazebo-config-version.cmake
      DESTINATION ${CATKIN_GLOBAL_SHARE_DESTINATION}/gazebo/cmake)
    install(FILES ${out}/gazebo.pc DESTINATION ${CATKIN_GLOBAL_LIB_DESTINATION}/pkgconfig)
  endif()
endforeach()

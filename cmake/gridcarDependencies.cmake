# Finds gridcar's dependencies (Debian bookworm packages) and wraps the ones that ship no
# imported target. Used by the build and, installed, by gridcarConfig.cmake, so that consumers
# of gridcar::gridcar get the same targets.
include(CMakeFindDependencyMacro)

# OMPL 1.5.2 from Debian exports only variables: wrap them once in gridcar::ompl.
find_dependency(ompl)
if(NOT TARGET gridcar::ompl)
  add_library(gridcar::ompl INTERFACE IMPORTED)
  set_target_properties(gridcar::ompl PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OMPL_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${OMPL_LIBRARIES}")
  # OMPL's Boost.Serialization use needs the library on the link line (Debian issue).
  find_dependency(Boost COMPONENTS serialization)
  set_property(TARGET gridcar::ompl APPEND PROPERTY INTERFACE_LINK_LIBRARIES Boost::serialization)
endif()

find_dependency(fcl)          # FCL 0.7: target `fcl`
find_dependency(Eigen3)       # Eigen3::Eigen

# Build-only dependencies (private to the library); skipped for consumers.
if(NOT GRIDCAR_CONSUMER)
  find_package(yaml-cpp REQUIRED)
  find_package(CLI11 REQUIRED)
  find_package(nlohmann_json REQUIRED)
  find_package(PkgConfig REQUIRED)
  if(NOT TARGET gridcar::stb)
    pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
    add_library(gridcar::stb INTERFACE IMPORTED)
    set_target_properties(gridcar::stb PROPERTIES INTERFACE_LINK_LIBRARIES PkgConfig::STB)
  endif()
endif()

# Every dependency is a Debian 12 package; nothing is downloaded.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(pugixml REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(tinyobjloader REQUIRED)

# VTK: the normal way first, then ParaView's own VTK (paraview-dev), which can
# live beside python3-paraview on one machine (libvtk9-dev cannot).
# IOPLY: the tests read the PLY export back through VTK.
set(SOAK_VTK_COMPONENTS CommonCore CommonDataModel IOXML IOCore IOPLY FiltersCore)
find_package(VTK QUIET COMPONENTS ${SOAK_VTK_COMPONENTS})
if(NOT VTK_FOUND)
  find_package(VTK REQUIRED COMPONENTS ${SOAK_VTK_COMPONENTS}
    PATHS /usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk
          /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-5.11/vtk
    NO_DEFAULT_PATH)
endif()
message(STATUS "Soak: VTK ${VTK_VERSION} from ${VTK_DIR}")

# OpenVDB (libopenvdb-dev): water as .vdb for Houdini and Blender. Debian
# ships its find module beside the library.
list(APPEND CMAKE_MODULE_PATH /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB /usr/lib/x86_64-linux-gnu/cmake/OpenVDB)
find_package(OpenVDB)
if(NOT OpenVDB_FOUND)
  message(FATAL_ERROR "Soak needs OpenVDB for its .vdb output: install libopenvdb-dev and libboost-iostreams-dev "
                      "(Demos/scripts/install-deps.sh installs every package the build needs)")
endif()
message(STATUS "Soak: OpenVDB ${OpenVDB_VERSION}")

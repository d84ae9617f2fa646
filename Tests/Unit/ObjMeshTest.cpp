#include <gtest/gtest.h>

#include <fstream>

#include "Base/Error.h"
#include "Scene/TriangleMesh.h"

using namespace soak;

namespace {
std::string writeObj(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}
std::string errorOf(const std::string& name, const std::string& text) {
  try {
    loadObjMesh(writeObj(name, text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(ObjMesh, LoadsAndTriangulatesQuads) {
  TriangleMesh m = loadObjMesh(writeObj("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
  EXPECT_EQ(m.vertices.size(), 4u);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_FLOAT_EQ(m.vertices[2].y, 1.f);
}

TEST(ObjMesh, RejectsBadMeshesWithFileName) {
  EXPECT_NE(errorOf("empty.obj", "").find("no triangles"), std::string::npos);
  std::string nan = errorOf("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(nan.find("nan.obj:2"), std::string::npos) << nan;
  EXPECT_NE(nan.find("not a finite number"), std::string::npos) << nan;
  std::string e = errorOf("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  EXPECT_TRUE(e.find("out of range") != std::string::npos || e.find("cannot read") != std::string::npos) << e;
  EXPECT_NE(errorOf("degen.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n").find("zero area"), std::string::npos);
  e = errorOf("fan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 2 5\n");
  EXPECT_NE(e.find("more than two triangles"), std::string::npos) << e;
  EXPECT_NE(e.find("fan.obj"), std::string::npos) << e;
  try {
    loadObjMesh("/nonexistent/cloth.obj");
    FAIL();
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("/nonexistent/cloth.obj"), std::string::npos);
  }
}

// OBJ and PLY readers: every form the spec allows, and the errors it requires.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <functional>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "softraster/error.h"
#include "softraster/scene/mesh.h"
#include "test_support.h"

using namespace softraster;

namespace {

std::filesystem::path write_temp(const std::string& name, const std::string& contents) {
    return test::write_temp_file("softraster_mesh_tests", name, contents);
}

using test::error_of;

template <class T>
std::string bytes_of(T v, bool big_endian) {
    std::string s(sizeof(T), '\0');
    std::memcpy(s.data(), &v, sizeof(T));
    if (big_endian == (std::endian::native == std::endian::little)) std::reverse(s.begin(), s.end());
    return s;
}

}  // namespace

TEST(ObjLoader, CornerFormsNegativeIndicesAndFans) {
    const auto p = write_temp("forms.obj",
                              "# comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0.5\nvt 1 1\nvn 0 0 1\n"
                              "g group\nusemtl x\ns 1\nf 1/1/1 2/2/1 3/2/1 4/1/1\nf -4//-1 -3//-1 -2//-1\n");
    const Mesh m = load_obj(p);
    ASSERT_EQ(m.triangle_count(), 3u);  // quad fan (0,1,2), (0,2,3) + one triangle
    const MeshVertex& v0 = m.vertices[m.indices[0]];
    EXPECT_EQ(v0.uv, glm::vec2(0.5f, 0.0f));  // a vt with one number has v = 0
    EXPECT_EQ(v0.normal, glm::vec3(0, 0, 1));
    EXPECT_EQ(m.vertices[m.indices[4]].position, glm::vec3(1, 1, 0));
    EXPECT_EQ(m.vertices[m.indices[5]].position, glm::vec3(0, 1, 0));
    EXPECT_EQ(m.vertices[m.indices[6]].uv, glm::vec2(0, 0));  // no vt: (0, 0)
}

TEST(ObjLoader, MissingNormalsUseTheFaceNormalAndColorsDefaultToWhite) {
    const auto p = write_temp("face.obj", "v 0 0 0 1 0 0\nv 2 0 0\nv 0 0 -2\nf 1 2 3\n");
    const Mesh m = load_obj(p);
    ASSERT_EQ(m.triangle_count(), 1u);
    for (uint32_t i : m.indices) EXPECT_EQ(m.vertices[i].normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(m.vertices[m.indices[0]].color, glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(m.vertices[m.indices[1]].color, glm::vec4(1, 1, 1, 1));
}

TEST(ObjLoader, NonFinitePositionsAreKeptForTheRendererToSkip) {
    const Mesh m = load_obj(write_temp("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nv inf 1 1\nf 1 2 3\nf 2 3 4\n"));
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_TRUE(std::isnan(m.vertices[m.indices[0]].position.x));
}

TEST(ObjLoader, LinesAndPoints) {
    const Mesh m = load_obj(write_temp("lp.obj", "v 0 0 0 1 0 0\nv 1 0 0\nv 1 1 0\nvt 0.5 0.25\nl 1 2/1 3\np 3 1\nf 1 2 3\n"));
    EXPECT_EQ(m.triangle_count(), 1u);
    ASSERT_EQ(m.lines.size(), 4u);  // the polyline 1 2 3 as two segments
    EXPECT_EQ(m.vertices[m.lines[0]].position, glm::vec3(0, 0, 0));
    EXPECT_EQ(m.vertices[m.lines[0]].color, glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(m.lines[1], m.lines[2]);
    EXPECT_EQ(m.vertices[m.lines[1]].uv, glm::vec2(0.5f, 0.25f));
    ASSERT_EQ(m.points.size(), 2u);
    EXPECT_EQ(m.vertices[m.points[0]].position, glm::vec3(1, 1, 0));
    EXPECT_EQ(m.points[0], m.lines[3]);  // the same corner is one vertex
}

TEST(Mesh, PrimitiveIndices) {
    Mesh m;
    m.vertices.resize(4);
    m.indices = {0, 1, 2, 2, 1, 3};
    EXPECT_EQ(triangle_edges(m), (std::vector<uint32_t>{0, 1, 1, 2, 2, 0, 1, 3, 3, 2}));  // (2, 1) is (1, 2)
    EXPECT_EQ(primitive_indices(m, Topology::Lines), triangle_edges(m));
    EXPECT_EQ(primitive_indices(m, Topology::Points), (std::vector<uint32_t>{0, 1, 2, 3}));
    m.lines = {3, 0};
    m.points = {2};
    EXPECT_EQ(primitive_indices(m, Topology::Lines), (std::vector<uint32_t>{3, 0}));
    EXPECT_EQ(primitive_indices(m, Topology::Points), (std::vector<uint32_t>{2}));
    EXPECT_EQ(primitive_indices(m, Topology::Triangles), m.indices);
}

TEST(ObjLoader, Errors) {
    const std::pair<const char*, const char*> cases[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "index 0"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "out of range"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "out of range"},
        {"v 0 0 0\nv 1 0 0\nf 1 2\n", "at least 3 corners"},
        {"v 0 zero 0\n", "not a number"},
        {"v 0 0 0\nvn nan 0 1\n", "non-finite"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "bad vertex index"},
        {"PK\x03\x04garbage\n", "unknown statement"},
        {"v 0 0\n", "3 coordinates"},
    };
    int n = 0;
    for (const auto& [text, expected] : cases) {
        const auto p = write_temp("bad" + std::to_string(n++) + ".obj", text);
        const std::string err = error_of([&] { load_obj(p); });
        EXPECT_NE(err.find(expected), std::string::npos) << text << " -> " << err;
        EXPECT_NE(err.find(p.string()), std::string::npos) << err;  // names the file
    }
    EXPECT_NE(error_of([] { load_obj("/nonexistent/x.obj"); }).find("file not found"), std::string::npos);
    // Line numbers.
    EXPECT_NE(error_of([] { load_obj(write_temp("line.obj", "v 0 0 0\n\nv a 0 0\n")); }).find(".obj:3:"), std::string::npos);
}

TEST(PlyLoader, AsciiWithColorsAndUv) {
    const auto p = write_temp("a.ply",
                              "ply\nformat ascii 1.0\ncomment x\nelement vertex 4\nproperty float x\nproperty float y\n"
                              "property float z\nproperty float s\nproperty float t\nproperty uchar red\n"
                              "property uchar green\nproperty uchar blue\nelement face 1\n"
                              "property list uchar int vertex_indices\nend_header\n"
                              "0 0 0 0 0 255 0 0\n1 0 0 1 0 0 255 0\n1 1 0 1 1 0 0 255\n0 1 0 0 1 255 255 255\n4 0 1 2 3\n");
    const Mesh m = load_ply(p);
    ASSERT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.vertices[m.indices[1]].color, glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(m.vertices[m.indices[2]].uv, glm::vec2(1, 1));
    EXPECT_EQ(m.vertices[m.indices[0]].normal, glm::vec3(0, 0, 1));  // face normal
}

TEST(PlyLoader, BinaryBothEndiannessesAndTypes) {
    for (bool be : {false, true}) {
        std::string body;
        const float pos[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        for (auto& v : pos) {
            body += bytes_of<double>(v[0], be) + bytes_of<float>(v[1], be) + bytes_of<int16_t>(int16_t(v[2]), be);
            body += bytes_of<float>(0, be) + bytes_of<float>(0, be) + bytes_of<float>(1, be);  // normal
            body += bytes_of<uint32_t>(7, be);                                              // skipped
        }
        body += bytes_of<uint8_t>(3, be) + bytes_of<uint16_t>(0, be) + bytes_of<uint16_t>(1, be) + bytes_of<uint16_t>(2, be);
        body += bytes_of<int8_t>(-5, be);  // extra face property
        const std::string header = std::string("ply\nformat ") + (be ? "binary_big_endian" : "binary_little_endian") +
                                   " 1.0\nelement vertex 3\nproperty double x\nproperty float32 y\nproperty short z\n"
                                   "property float nx\nproperty float ny\nproperty float nz\nproperty uint flags\n"
                                   "element face 1\nproperty list uint8 ushort vertex_index\nproperty char extra\nend_header\n";
        const Mesh m = load_ply(write_temp(be ? "be.ply" : "le.ply", header + body));
        ASSERT_EQ(m.triangle_count(), 1u);
        EXPECT_EQ(m.vertices[1].position, glm::vec3(1, 0, 0));
        EXPECT_EQ(m.vertices[2].normal, glm::vec3(0, 0, 1));
    }
}

TEST(PlyLoader, Errors) {
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::pair<std::string, const char*> cases[] = {
        {head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "out of range"},
        {head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "out of range"},
        {head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 x\n", "not an integer"},
        {head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n", "not an integer"},
        {head + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "corners"},
        {head + "0 0 0\n1 0 0\n", "ends early"},
        {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nbogus\nend_header\n", "unexpected header line"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "end_header"},
        {"solid cube\n", "not a PLY"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty int red\n"
         "property int green\nproperty int blue\nend_header\n0 0 0 1 1 1\n", "color"},
        {"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\nabc", "truncated"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
         "property float ny\nproperty float nz\nend_header\n0 0 0 nan 0 1\n", "non-finite"},
    };
    int n = 0;
    for (const auto& [text, expected] : cases) {
        const auto p = write_temp("bad" + std::to_string(n++) + ".ply", text);
        const std::string err = error_of([&] { load_ply(p); });
        EXPECT_NE(err.find(expected), std::string::npos) << text << " -> " << err;
        EXPECT_NE(err.find(p.string()), std::string::npos) << err;
    }
}

TEST(PlyLoader, NoFacesDrawsNothing) {
    const Mesh m = load_ply(write_temp("empty.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                                    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n"));
    EXPECT_EQ(m.triangle_count(), 0u);
}

// OBJ files as common tools write them: a UTF-8 byte-order mark, CRLF line ends, tabs,
// backslash continuations, and o/g/s/usemtl/mtllib statements; an error in a continued
// statement names its first line.
TEST(ObjLoader, FilesAsToolsWriteThem) {
    const std::string text = "\xEF\xBB\xBF# exported\r\nmtllib a.mtl\r\no Cube\r\ng side\r\nv\t0 0 0\r\nv 1 0 0\r\n"
                             "v 1 1 0 \\\r\n\r\nv 0 1 0\r\nusemtl red\r\ns 1\r\nf 1 2 \\\r\n  3 4\r\ns off\r\n";
    const Mesh m = load_obj(write_temp("tools.obj", text));
    ASSERT_EQ(m.indices.size(), 6u);  // one quad, two triangles
    EXPECT_EQ(m.vertices.size(), 6u);  // (face normals: three vertices per triangle)
    EXPECT_EQ(m.vertices[2].position, glm::vec3(1, 1, 0));
    const std::string error = error_of([] { load_obj(write_temp("cont.obj", "v 0 0 0\nf 1 \\\n 2 x\n")); });
    EXPECT_NE(error.find("cont.obj:2:"), std::string::npos) << error;
}

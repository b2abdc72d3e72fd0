// The one copy of the shared test shaders' pipelines (see the end of test_support.h).
#include "test_support.h"

namespace softraster::test {
template SamplePicture draw_rgb_meshes<true>(int, int, int, DepthCase, const std::vector<RgbMesh>&, std::atomic<uint64_t>*, bool,
                                            Context::Batching);
template SamplePicture draw_rgb_meshes<false>(int, int, int, DepthCase, const std::vector<RgbMesh>&, std::atomic<uint64_t>*, bool,
                                             Context::Batching);
template void draw<ConstantColorShader>(Context&, const ConstantColorShader&, const std::vector<ClipVertexIn>&,
                                        const std::vector<uint32_t>&, Topology);
}  // namespace softraster::test

// A scene object's keys (docs/scene-format.md: "depth", "stencil", "scissor", the material's
// blending, color mask, alpha cutoff, alpha-to-coverage and interpolation) as the pipeline's
// RenderState.
#include "scene/object_state.h"

namespace softraster {

RenderState render_state(const SceneObject& o, int supersample) {
    RenderState st;
    st.cull = o.cull;
    st.front_face = o.front_face;
    st.depth_test = o.state.depth_test;
    st.depth_func = o.state.depth_func;
    st.polygon_offset_factor = o.state.offset_factor;
    st.polygon_offset_units = o.state.offset_units;
    st.stencil_test = o.state.stencil_test;
    st.stencil_front = o.state.stencil_front;
    st.stencil_back = o.state.stencil_back;
    if (o.state.scissor) {
        const ScissorRect& r = *o.state.scissor;
        st.scissor_test = true;
        st.scissor = {r.x * supersample, r.y * supersample, r.width * supersample, r.height * supersample};
    }
    const Material& m = o.material;
    st.blend = m.blend;
    st.blend_equation = m.blend_equation;
    st.color_write = m.color_mask != 0;
    st.color_mask = m.color_mask;
    st.alpha_test = m.alpha_cutoff.has_value();
    st.alpha_cutoff = m.alpha_cutoff.value_or(0.5f);
    st.alpha_to_coverage = m.alpha_to_coverage;
    st.noperspective = m.affine;
    st.line_width = o.line_width;
    st.point_size = o.point_size;
    return st;
}

}  // namespace softraster

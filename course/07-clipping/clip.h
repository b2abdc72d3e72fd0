// Lesson 7: clipping. Polygons against the view volume in homogeneous clip space
// (Sutherland-Hodgman), and lines against a rectangle on the screen (Cohen-Sutherland).
#pragma once
#include <vector>

#include <glm/glm.hpp>

namespace course {

// A corner in clip space (before the divide) with a color to carry along.
struct ClipCorner {
    glm::vec4 position;
    glm::vec3 color;
};

// The view volume in clip space is -w <= x, y, z <= w: six planes, each "inside" where
// dot(plane, p) >= 0. Testing before the divide is what makes points behind the camera
// (w < 0) harmless: they are simply outside the near plane z >= -w.
inline const glm::vec4 kFrustumPlanes[6] = {{0, 0, 1, 1}, {0, 0, -1, 1},   // near (z >= -w), far (z <= w)
                                            {1, 0, 0, 1}, {-1, 0, 0, 1},   // left, right
                                            {0, 1, 0, 1}, {0, -1, 0, 1}};  // bottom, top

// Sutherland-Hodgman (Sutherland & Hodgman 1974): walk the polygon's edges and keep what is
// inside one plane; where an edge crosses it, add the crossing point, at t = d_in / (d_in - d_out)
// of the way from the inside end (so two polygons that share the edge get the same point);
// then do the next plane with the result. A triangle can come out with up to 9 corners, or none.
inline std::vector<ClipCorner> clip_to_plane(const std::vector<ClipCorner>& polygon, const glm::vec4& plane) {
    std::vector<ClipCorner> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const ClipCorner& cur = polygon[i];
        const ClipCorner& next = polygon[(i + 1) % polygon.size()];
        const float dc = glm::dot(plane, cur.position), dn = glm::dot(plane, next.position);
        if (dc >= 0.0f) out.push_back(cur);
        if ((dc >= 0.0f) != (dn >= 0.0f)) {
            const ClipCorner& in = dc >= 0.0f ? cur : next;
            const ClipCorner& outside = dc >= 0.0f ? next : cur;
            const float d_in = dc >= 0.0f ? dc : dn, d_out = dc >= 0.0f ? dn : dc;
            const float t = d_in / (d_in - d_out);
            out.push_back({in.position + t * (outside.position - in.position), in.color + t * (outside.color - in.color)});
        }
    }
    return out;
}

inline std::vector<ClipCorner> clip_to_frustum(std::vector<ClipCorner> polygon, int planes = 6) {
    for (int p = 0; p < planes && polygon.size() >= 3; ++p) polygon = clip_to_plane(polygon, kFrustumPlanes[p]);
    return polygon.size() >= 3 ? polygon : std::vector<ClipCorner>{};
}

// Cohen-Sutherland (Cohen & Sutherland 1967) for a segment and the rectangle [x0, x1] x [y0, y1].
// Each end gets a 4-bit outcode (区域码): left, right, below, above the rectangle. Both codes
// 0: wholly inside, keep it. Codes sharing a bit: both ends beyond the same side, drop it.
// Otherwise move an outside end to where the segment crosses the side its code names, and
// look again.
struct Segment2 {
    glm::vec2 a, b;
};
enum : unsigned { kLeft = 1, kRight = 2, kBelow = 4, kAbove = 8 };
inline unsigned outcode(glm::vec2 p, glm::vec2 lo, glm::vec2 hi) {
    return (p.x < lo.x ? kLeft : 0u) | (p.x > hi.x ? kRight : 0u) | (p.y < lo.y ? kBelow : 0u) | (p.y > hi.y ? kAbove : 0u);
}
inline bool clip_cohen_sutherland(Segment2& s, glm::vec2 lo, glm::vec2 hi) {
    unsigned ca = outcode(s.a, lo, hi), cb = outcode(s.b, lo, hi);
    for (int round = 0; round < 8; ++round) {  // (each side at most once per end; rounding near a corner could ping-pong)
        if ((ca | cb) == 0) return true;   // trivially accepted
        if ((ca & cb) != 0) return false;  // trivially rejected
        const unsigned c = ca ? ca : cb;   // an end outside
        const glm::vec2 d = s.b - s.a;
        glm::vec2 p;
        if (c & kLeft) p = {lo.x, s.a.y + d.y * (lo.x - s.a.x) / d.x};
        else if (c & kRight) p = {hi.x, s.a.y + d.y * (hi.x - s.a.x) / d.x};
        else if (c & kBelow) p = {s.a.x + d.x * (lo.y - s.a.y) / d.y, lo.y};
        else p = {s.a.x + d.x * (hi.y - s.a.y) / d.y, hi.y};
        if (c == ca) s.a = p, ca = outcode(p, lo, hi);
        else s.b = p, cb = outcode(p, lo, hi);
    }
    return false;
}

}  // namespace course

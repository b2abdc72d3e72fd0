// The few types every stage shares: the kinds of primitive, pixel rectangles and the grid
// of tiles the picture is cut into. Front end and back end both include this header and
// not each other.
#pragma once
#include <algorithm>
#include <climits>

namespace softraster {

enum class Topology { Triangles, Lines, Points };

// Half-open pixel rectangle [x0, x1) x [y0, y1): the viewport, a tile, a triangle's bounds.
struct Rect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
};

inline Rect intersect(const Rect& a, const Rect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

inline constexpr int kTileSize = 64;  // pixels, as llvmpipe

// The picture in kTileSize x kTileSize tiles, numbered row by row.
struct TileGrid {
    int width = 0, height = 0, tiles_x = 0, tiles_y = 0;
    TileGrid() = default;
    TileGrid(int w, int h) : width(w), height(h), tiles_x((w + kTileSize - 1) / kTileSize), tiles_y((h + kTileSize - 1) / kTileSize) {}
    int count() const { return tiles_x * tiles_y; }
    // Tile t's column and row, and back.
    int tile_x(int t) const { return t % tiles_x; }
    int tile_y(int t) const { return t / tiles_x; }
    int tile_index(int tx, int ty) const { return ty * tiles_x + tx; }
    Rect tile_rect(int t) const {
        const int x = tile_x(t) * kTileSize, y = tile_y(t) * kTileSize;
        return {x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)};
    }
};

// A rectangle of tiles [x0, x1) x [y0, y1), in tile units: the tiles a draw touches.
struct TileRange {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int count() const { return x1 > x0 && y1 > y0 ? (x1 - x0) * (y1 - y0) : 0; }
    bool contains(int tx, int ty) const { return tx >= x0 && tx < x1 && ty >= y0 && ty < y1; }
    // Index of tile (tx, ty) within the range, row by row; -1 outside it.
    int local(int tx, int ty) const { return contains(tx, ty) ? (ty - y0) * (x1 - x0) + (tx - x0) : -1; }
};

// The smallest TileRange holding rectangles of tiles given one at a time: binning widens it
// once per triangle, so it starts inverted (holding nothing) and widens without a branch.
struct TileBounds {
    int x0 = INT_MAX, y0 = INT_MAX, x1 = INT_MIN, y1 = INT_MIN;
    // Tiles [tx0, tx1] x [ty0, ty1], inclusive.
    void include(int tx0, int ty0, int tx1, int ty1) {
        x0 = std::min(x0, tx0), y0 = std::min(y0, ty0), x1 = std::max(x1, tx1 + 1), y1 = std::max(y1, ty1 + 1);
    }
    TileRange range() const { return x0 < x1 && y0 < y1 ? TileRange{x0, y0, x1, y1} : TileRange{}; }
};

}  // namespace softraster

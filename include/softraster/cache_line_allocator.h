// Storage on cache lines of its own: it starts on a line and takes whole lines, so nothing
// else the C library hands out shares a line with it.
//
// Two threads that write buffers side by side in memory bounce the line they share between
// their cores at every write, though neither reads the other's data:
//   - the framebuffer's planes: threads draw different tiles at once (64 pixels wide, 256
//     bytes of color and of depth a row); with each plane starting on a line, as do its rows
//     where a row's bytes are a multiple of 64, no line holds two tiles' pixels (a large
//     std::vector's data sits 16 bytes past a page start);
//   - a thread's scratch of the front end (a small draw's clip parts, its pending tile
//     pairs), written at every draw: the calling thread's lay in the main heap among blocks
//     the workers write, and its small draws took 1.5 to 1.8 times as long as a worker's
//     (docs/performance.md, "Scratch on lines of its own").
#pragma once
#include <cstddef>
#include <memory>
#include <new>

namespace softraster {

inline constexpr size_t kCacheLine = 64;

// `bytes` rounded up to whole lines.
inline constexpr size_t whole_cache_lines(size_t bytes) { return (bytes + kCacheLine - 1) / kCacheLine * kCacheLine; }

template <class T>
struct CacheLineAllocator {
    using value_type = T;
    static constexpr std::align_val_t kLine{kCacheLine};
    CacheLineAllocator() = default;
    template <class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) {}
    T* allocate(size_t n) { return static_cast<T*>(::operator new(whole_cache_lines(n * sizeof(T)), kLine)); }
    void deallocate(T* p, size_t n) { ::operator delete(p, whole_cache_lines(n * sizeof(T)), kLine); }
    bool operator==(const CacheLineAllocator&) const = default;
};

// A buffer of bytes on lines of its own, not initialized (a std::vector would zero them
// each time it grew): the blocks of Context's post-transform vertices, written anew batch
// after batch and replaced by a bigger one when they no longer fit.
class CacheLineBlock {
public:
    CacheLineBlock() = default;
    explicit CacheLineBlock(size_t bytes)
        : memory_(static_cast<std::byte*>(::operator new(whole_cache_lines(bytes), std::align_val_t(kCacheLine)))), size_(bytes) {}
    std::byte* data() const { return memory_.get(); }
    size_t size() const { return size_; }

private:
    struct Delete {
        void operator()(std::byte* p) const { ::operator delete(p, std::align_val_t(kCacheLine)); }
    };
    std::unique_ptr<std::byte, Delete> memory_;
    size_t size_ = 0;
};

}  // namespace softraster

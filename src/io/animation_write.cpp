#include "softraster/io/animation_write.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <regex>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "softraster/error.h"
#include "softraster/io/image_write.h"

extern "C" {
#include <gif_lib.h>
#include <libimagequant.h>
}

#include "io/modules.h"
#include "io/video_module.h"

namespace softraster {
namespace {

enum class Kind { Video, Gif, Numbered };

std::string lower_extension(const std::filesystem::path& p) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

// One printf conversion for the frame number: %d or %0Nd.
const std::regex kNumber("%(0[1-9][0-9]?)?d");

Kind kind_of(const std::filesystem::path& out) {
    const std::string name = out.filename().string();
    const auto numbers = std::distance(std::sregex_iterator(name.begin(), name.end(), kNumber), std::sregex_iterator());
    const bool stray_percent = std::count(name.begin(), name.end(), '%') != numbers;
    if (numbers > 0) {
        if (numbers != 1 || stray_percent)
            throw InputError(out.string() + ": a numbered frame name holds one %d or %0Nd (e.g. frames/%04d.png)");
        if (!picture_format(out)) throw InputError(out.string() + ": unknown picture extension for numbered frames (.png, .tga, .ppm, .exr)");
        return Kind::Numbered;
    }
    const std::string e = lower_extension(out);
    if (e == ".gif") return Kind::Gif;
    if (e == ".mp4" || e == ".webm") return Kind::Video;
    throw InputError(out.string() + ": an animation is .mp4, .webm, .gif or numbered pictures (frames/%04d.png)");
}

std::filesystem::path temporary_name(const std::filesystem::path& out) {
    std::filesystem::path t = out;
    t += ".part";
    return t;
}

// The file under its temporary name until commit(); removed if never committed.
class PendingFile {
public:
    explicit PendingFile(std::filesystem::path out) : out_(std::move(out)), temp_(temporary_name(out_)) {}
    ~PendingFile() {
        std::error_code ec;
        if (!committed_) std::filesystem::remove(temp_, ec);
    }
    const std::filesystem::path& temp() const { return temp_; }
    void commit() {
        std::error_code ec;
        std::filesystem::rename(temp_, out_, ec);
        if (ec) throw std::runtime_error(out_.string() + ": cannot move into place: " + ec.message());
        committed_ = true;
    }

private:
    std::filesystem::path out_, temp_;
    bool committed_ = false;
};

// ---- numbered pictures

class NumberedWriter final : public AnimationWriter {
public:
    NumberedWriter(const std::filesystem::path& out, ColorSpace color) : pattern_(out.string()), color_(color) {
        std::error_code ec;
        if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path(), ec);
        if (ec) throw std::runtime_error(out.parent_path().string() + ": cannot create the folder: " + ec.message());
    }
    void add(const Image& frame) override { write_picture(frame, numbered_frame(pattern_, next_++), color_); }
    void finish() override {}

private:
    std::string pattern_;
    ColorSpace color_;
    int next_ = 0;
};

// ---- GIF: libimagequant picks each frame's palette, giflib writes it

class GifWriter final : public AnimationWriter {
public:
    GifWriter(const std::filesystem::path& out, int width, int height, int fps) : file_(out), width_(width), height_(height), fps_(fps) {
        if (width > 65535 || height > 65535) throw InputError(out.string() + ": a GIF is at most 65535 pixels a side");
        int error = 0;
        const int fd = ::open(file_.temp().c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);  // (giflib's own open makes it 0600)
        if (fd < 0) throw std::runtime_error(out.string() + ": cannot write");
        gif_.reset(EGifOpenFileHandle(fd, &error));
        if (!gif_) ::close(fd);
        if (!gif_) throw std::runtime_error(out.string() + ": cannot write: " + GifErrorString(error));
        EGifSetGifVersion(gif_.get(), true);
        check(EGifPutScreenDesc(gif_.get(), width, height, 8, 0, nullptr));
        // NETSCAPE2.0: loop forever.
        static const unsigned char kLoop[3] = {1, 0, 0};
        check(EGifPutExtensionLeader(gif_.get(), APPLICATION_EXT_FUNC_CODE));
        check(EGifPutExtensionBlock(gif_.get(), 11, "NETSCAPE2.0"));
        check(EGifPutExtensionBlock(gif_.get(), 3, kLoop));
        check(EGifPutExtensionTrailer(gif_.get()));
    }
    void add(const Image& frame) override {
        liq_attr* attr = liq_attr_create();
        liq_set_max_colors(attr, 256);
        liq_image* image = liq_image_create_rgba(attr, frame.pixels.data(), width_, height_, 0);
        liq_result* result = nullptr;
        std::vector<unsigned char> indices(size_t(width_) * size_t(height_));
        const bool ok = image && liq_image_quantize(image, attr, &result) == LIQ_OK && liq_set_dithering_level(result, 1.0f) == LIQ_OK &&
                        liq_write_remapped_image(result, image, indices.data(), indices.size()) == LIQ_OK;
        ColorMapObject* map = GifMakeMapObject(256, nullptr);
        if (ok) {
            const liq_palette* palette = liq_get_palette(result);
            for (unsigned i = 0; i < palette->count; ++i) map->Colors[i] = {palette->entries[i].r, palette->entries[i].g, palette->entries[i].b};
        }
        if (result) liq_result_destroy(result);
        if (image) liq_image_destroy(image);
        liq_attr_destroy(attr);
        if (!ok || !map) {
            if (map) GifFreeMapObject(map);
            throw std::runtime_error(file_.temp().string() + ": libimagequant could not quantize a frame");
        }
        // Delays in hundredths of a second, rounded so that the total stays on time.
        GraphicsControlBlock gcb{};
        gcb.DisposalMode = DISPOSE_DO_NOT;
        gcb.TransparentColor = NO_TRANSPARENT_COLOR;
        gcb.DelayTime = int(std::lround(100.0 * (frames_ + 1) / fps_) - std::lround(100.0 * frames_ / fps_));
        GifByteType extension[4];
        const size_t n = EGifGCBToExtension(&gcb, extension);
        const bool written = EGifPutExtension(gif_.get(), GRAPHICS_EXT_FUNC_CODE, int(n), extension) == GIF_OK &&
                             EGifPutImageDesc(gif_.get(), 0, 0, width_, height_, false, map) == GIF_OK;
        GifFreeMapObject(map);
        check(written ? GIF_OK : GIF_ERROR);
        for (int y = 0; y < height_; ++y) check(EGifPutLine(gif_.get(), indices.data() + size_t(y) * size_t(width_), width_));
        ++frames_;
    }
    void finish() override {
        int error = 0;
        const int closed = EGifCloseFile(gif_.release(), &error);
        if (closed != GIF_OK) throw std::runtime_error(file_.temp().string() + ": " + GifErrorString(error));
        file_.commit();
    }

private:
    void check(int status) const {
        if (status != GIF_OK) throw std::runtime_error(file_.temp().string() + ": " + GifErrorString(gif_->Error));
    }
    // (Closed however the writer ends, a throw in the constructor included.)
    struct Close {
        void operator()(GifFileType* g) const { EGifCloseFile(g, nullptr); }
    };
    PendingFile file_;
    int width_, height_, fps_;
    std::unique_ptr<GifFileType, Close> gif_;
    int frames_ = 0;
};

// ---- video: FFmpeg's libavcodec encodes, libavformat writes the container, in the video
// module (video_module.h), opened with the first video

const SoftrasterVideoApi& video_api(const std::filesystem::path& out) {
    return *reinterpret_cast<SoftrasterVideoApiFn>(
        required_module_entry(SOFTRASTER_VIDEO_MODULE, SOFTRASTER_VIDEO_API, out.string() + ": writing a video needs softraster's FFmpeg module"))();
}

class VideoWriter final : public AnimationWriter {
public:
    VideoWriter(const std::filesystem::path& out, int width, int height, int fps) : file_(out), api_(video_api(out)) {
        if (width % 2 || height % 2)
            throw InputError(out.string() + ": a video needs an even width and height (got " + std::to_string(width) + "x" +
                             std::to_string(height) + ")");
        video_.reset(api_.open(file_.temp().c_str(), out.c_str(), lower_extension(out) == ".webm", width, height, fps, error_, sizeof error_));
        if (!video_) throw std::runtime_error(error_);
    }
    void add(const Image& frame) override {
        if (!api_.add(video_.get(), reinterpret_cast<const uint8_t*>(frame.pixels.data()), error_, sizeof error_)) throw std::runtime_error(error_);
    }
    void finish() override {
        if (!api_.finish(video_.get(), error_, sizeof error_)) throw std::runtime_error(error_);
        file_.commit();
    }

private:
    struct Close {
        void (*close)(SoftrasterVideo*);
        void operator()(SoftrasterVideo* v) const { close(v); }
    };
    PendingFile file_;  // (declared first: the video is closed before an unfinished file is removed)
    const SoftrasterVideoApi& api_;
    char error_[512] = {};
    std::unique_ptr<SoftrasterVideo, Close> video_{nullptr, Close{api_.close}};
};

}  // namespace

std::string numbered_frame(const std::string& pattern, int k) {
    std::smatch m;
    if (!std::regex_search(pattern, m, kNumber)) return pattern;
    const int width = m[1].length() ? std::stoi(m[1].str()) : 0;  // "%05d": 5
    char number[32];
    std::snprintf(number, sizeof number, "%0*d", width, k);
    std::string name = m.prefix().str();  // (appended piece by piece: g++ 12 warns falsely on a + b + c)
    name += number;
    name += m.suffix().str();
    return name;
}

void check_animation_path(const std::filesystem::path& out) {
    // A single file goes into a folder that must exist (numbered pictures make theirs).
    std::error_code ec;
    if (kind_of(out) != Kind::Numbered && out.has_parent_path() && !std::filesystem::is_directory(out.parent_path(), ec))
        throw InputError(out.string() + ": output folder '" + out.parent_path().string() + "' does not exist");
}

std::unique_ptr<AnimationWriter> open_animation(const std::filesystem::path& out, int width, int height, int fps, ColorSpace color) {
    if (fps < 1) throw InputError("frames per second must be at least 1");
    switch (kind_of(out)) {
        case Kind::Numbered: return std::make_unique<NumberedWriter>(out, color);
        case Kind::Gif: return std::make_unique<GifWriter>(out, width, height, fps);
        case Kind::Video: return std::make_unique<VideoWriter>(out, width, height, fps);
    }
    return nullptr;
}

}  // namespace softraster

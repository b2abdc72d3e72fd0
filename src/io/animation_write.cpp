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
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
#include <libimagequant.h>
}

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

// ---- video: FFmpeg's libavcodec encodes, libavformat writes the container

class VideoWriter final : public AnimationWriter {
public:
    VideoWriter(const std::filesystem::path& out, int width, int height, int fps) : file_(out), width_(width), height_(height) {
        av_log_set_level(AV_LOG_ERROR);  // (the encoders' statistics are not for the user)
        if (width % 2 || height % 2)
            throw InputError(out.string() + ": a video needs an even width and height (got " + std::to_string(width) + "x" +
                             std::to_string(height) + ")");
        const bool webm = lower_extension(out) == ".webm";
        const AVCodec* codec = webm ? avcodec_find_encoder_by_name("libvpx-vp9") : avcodec_find_encoder_by_name("libx264");
        if (!codec) codec = avcodec_find_encoder(webm ? AV_CODEC_ID_VP8 : AV_CODEC_ID_MPEG4);
        if (!codec) throw std::runtime_error(out.string() + ": FFmpeg has no encoder for this format");
        if (avformat_alloc_output_context2(&av_.format, nullptr, webm ? "webm" : "mp4", file_.temp().c_str()) < 0 || !av_.format)
            throw std::runtime_error(out.string() + ": FFmpeg cannot write this format");
        stream_ = avformat_new_stream(av_.format, nullptr);
        av_.codec = avcodec_alloc_context3(codec);
        if (!stream_ || !av_.codec) throw std::runtime_error(out.string() + ": out of memory");
        av_.codec->width = width;
        av_.codec->height = height;
        av_.codec->time_base = AVRational{1, fps};
        av_.codec->framerate = AVRational{fps, 1};
        av_.codec->pix_fmt = AV_PIX_FMT_YUV420P;
        av_.codec->gop_size = 2 * fps;
        // No B-frames: frames then leave the encoder in order, and MP4's edit list (which
        // reorder delay needs) would cut the last frame short in some players and probes.
        av_.codec->max_b_frames = 0;
        av_.codec->colorspace = AVCOL_SPC_SMPTE170M;
        av_.codec->color_range = AVCOL_RANGE_MPEG;
        if (av_.format->oformat->flags & AVFMT_GLOBALHEADER) av_.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        if (codec->id == AV_CODEC_ID_H264) {
            av_opt_set(av_.codec->priv_data, "preset", "medium", 0);
            av_opt_set(av_.codec->priv_data, "crf", "18", 0);
        } else if (codec->id == AV_CODEC_ID_VP9 || codec->id == AV_CODEC_ID_VP8) {
            av_opt_set(av_.codec->priv_data, "crf", "24", 0);
            av_.codec->bit_rate = 0;
            av_opt_set(av_.codec->priv_data, "deadline", "good", 0);
            av_opt_set(av_.codec->priv_data, "cpu-used", "4", 0);
        } else {
            av_.codec->bit_rate = int64_t(width) * height * fps / 4;
        }
        if (avcodec_open2(av_.codec, codec, nullptr) < 0) throw std::runtime_error(out.string() + ": cannot open the encoder");
        if (avcodec_parameters_from_context(stream_->codecpar, av_.codec) < 0) throw std::runtime_error(out.string() + ": encoder parameters");
        stream_->time_base = av_.codec->time_base;
        if (avio_open(&av_.format->pb, file_.temp().c_str(), AVIO_FLAG_WRITE) < 0) throw std::runtime_error(out.string() + ": cannot write");
        if (avformat_write_header(av_.format, nullptr) < 0) throw std::runtime_error(out.string() + ": cannot write the header");
        av_.frame = av_frame_alloc();
        av_.packet = av_packet_alloc();
        if (!av_.frame || !av_.packet) throw std::runtime_error(out.string() + ": out of memory");
        av_.frame->format = av_.codec->pix_fmt;
        av_.frame->width = width;
        av_.frame->height = height;
        if (av_frame_get_buffer(av_.frame, 0) < 0) throw std::runtime_error(out.string() + ": out of memory");
        av_.scale = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
        if (!av_.scale) throw std::runtime_error(out.string() + ": cannot convert RGBA to YUV");
    }
    void add(const Image& frame) override {
        if (av_frame_make_writable(av_.frame) < 0) throw std::runtime_error(file_.temp().string() + ": frame buffer");
        const uint8_t* source[1] = {reinterpret_cast<const uint8_t*>(frame.pixels.data())};
        const int stride[1] = {4 * width_};
        sws_scale(av_.scale, source, stride, 0, height_, av_.frame->data, av_.frame->linesize);
        av_.frame->pts = next_pts_++;
        encode(av_.frame);
    }
    void finish() override {
        encode(nullptr);
        if (av_write_trailer(av_.format) < 0) throw std::runtime_error(file_.temp().string() + ": cannot finish the file");
        avio_closep(&av_.format->pb);
        file_.commit();
    }

private:
    void encode(AVFrame* frame) {
        if (avcodec_send_frame(av_.codec, frame) < 0) throw std::runtime_error(file_.temp().string() + ": the encoder refused a frame");
        for (;;) {
            const int r = avcodec_receive_packet(av_.codec, av_.packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            if (r < 0) throw std::runtime_error(file_.temp().string() + ": encoding failed");
            av_.packet->duration = 1;  // one frame (some encoders leave it 0: MP4 then ends at the last frame's start)
            av_packet_rescale_ts(av_.packet, av_.codec->time_base, stream_->time_base);
            av_.packet->stream_index = stream_->index;
            if (av_interleaved_write_frame(av_.format, av_.packet) < 0) throw std::runtime_error(file_.temp().string() + ": cannot write a frame");
        }
    }
    // FFmpeg's objects, freed however the writer ends (a throw in the constructor included:
    // then only this member's destructor runs, not the writer's).
    struct Contexts {
        AVFormatContext* format = nullptr;
        AVCodecContext* codec = nullptr;
        AVFrame* frame = nullptr;
        AVPacket* packet = nullptr;
        SwsContext* scale = nullptr;
        Contexts() = default;
        Contexts(const Contexts&) = delete;
        Contexts& operator=(const Contexts&) = delete;
        ~Contexts() {
            sws_freeContext(scale);
            av_packet_free(&packet);
            av_frame_free(&frame);
            avcodec_free_context(&codec);
            if (format) {
                if (format->pb) avio_closep(&format->pb);
                avformat_free_context(format);
            }
        }
    };
    PendingFile file_;
    int width_, height_;
    Contexts av_;
    AVStream* stream_ = nullptr;  // (owned by av_.format)
    int64_t next_pts_ = 0;
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

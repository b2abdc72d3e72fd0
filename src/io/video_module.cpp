// libsoftraster_video.so: videos encoded by FFmpeg's libavcodec and written by its
// libavformat (see video_module.h for why this is a module of its own).
#include "io/video_module.h"

#include <cstdio>
#include <stdexcept>
#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

struct SoftrasterVideo {
    // Opens the encoder and writes the header; throws std::runtime_error naming the file.
    SoftrasterVideo(const std::string& path, const std::string& name, bool webm, int width, int height, int fps)
        : path_(path), width_(width), height_(height) {
        av_log_set_level(AV_LOG_ERROR);  // (the encoders' statistics are not for the user)
        const AVCodec* codec = webm ? avcodec_find_encoder_by_name("libvpx-vp9") : avcodec_find_encoder_by_name("libx264");
        if (!codec) codec = avcodec_find_encoder(webm ? AV_CODEC_ID_VP8 : AV_CODEC_ID_MPEG4);
        if (!codec) throw std::runtime_error(name + ": FFmpeg has no encoder for this format");
        if (avformat_alloc_output_context2(&av_.format, nullptr, webm ? "webm" : "mp4", path.c_str()) < 0 || !av_.format)
            throw std::runtime_error(name + ": FFmpeg cannot write this format");
        stream_ = avformat_new_stream(av_.format, nullptr);
        av_.codec = avcodec_alloc_context3(codec);
        if (!stream_ || !av_.codec) throw std::runtime_error(name + ": out of memory");
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
        if (avcodec_open2(av_.codec, codec, nullptr) < 0) throw std::runtime_error(name + ": cannot open the encoder");
        if (avcodec_parameters_from_context(stream_->codecpar, av_.codec) < 0) throw std::runtime_error(name + ": encoder parameters");
        stream_->time_base = av_.codec->time_base;
        if (avio_open(&av_.format->pb, path.c_str(), AVIO_FLAG_WRITE) < 0) throw std::runtime_error(name + ": cannot write");
        if (avformat_write_header(av_.format, nullptr) < 0) throw std::runtime_error(name + ": cannot write the header");
        av_.frame = av_frame_alloc();
        av_.packet = av_packet_alloc();
        if (!av_.frame || !av_.packet) throw std::runtime_error(name + ": out of memory");
        av_.frame->format = av_.codec->pix_fmt;
        av_.frame->width = width;
        av_.frame->height = height;
        if (av_frame_get_buffer(av_.frame, 0) < 0) throw std::runtime_error(name + ": out of memory");
        av_.scale = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
        if (!av_.scale) throw std::runtime_error(name + ": cannot convert RGBA to YUV");
    }
    void add(const uint8_t* rgba) {
        if (av_frame_make_writable(av_.frame) < 0) throw std::runtime_error(path_ + ": frame buffer");
        const uint8_t* source[1] = {rgba};
        const int stride[1] = {4 * width_};
        sws_scale(av_.scale, source, stride, 0, height_, av_.frame->data, av_.frame->linesize);
        av_.frame->pts = next_pts_++;
        encode(av_.frame);
    }
    void finish() {
        encode(nullptr);
        if (av_write_trailer(av_.format) < 0) throw std::runtime_error(path_ + ": cannot finish the file");
        avio_closep(&av_.format->pb);
    }

private:
    void encode(AVFrame* frame) {
        if (avcodec_send_frame(av_.codec, frame) < 0) throw std::runtime_error(path_ + ": the encoder refused a frame");
        for (;;) {
            const int r = avcodec_receive_packet(av_.codec, av_.packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            if (r < 0) throw std::runtime_error(path_ + ": encoding failed");
            av_.packet->duration = 1;  // one frame (some encoders leave it 0: MP4 then ends at the last frame's start)
            av_packet_rescale_ts(av_.packet, av_.codec->time_base, stream_->time_base);
            av_.packet->stream_index = stream_->index;
            if (av_interleaved_write_frame(av_.format, av_.packet) < 0) throw std::runtime_error(path_ + ": cannot write a frame");
        }
    }
    // FFmpeg's objects, freed however the video ends (a throw in the constructor included:
    // then only this member's destructor runs, not the video's).
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
    std::string path_;
    int width_, height_;
    Contexts av_;
    AVStream* stream_ = nullptr;  // (owned by av_.format)
    int64_t next_pts_ = 0;
};

namespace {

// Runs f, turning what it throws into `error` (no exception crosses the module's edge).
template <class F>
bool reported(char* error, size_t error_size, F&& f) {
    try {
        f();
        return true;
    } catch (const std::exception& e) {
        std::snprintf(error, error_size, "%s", e.what());
    }
    return false;
}

const SoftrasterVideoApi kApi = {
    [](const char* path, const char* name, bool webm, int width, int height, int fps, char* error, size_t error_size) {
        SoftrasterVideo* video = nullptr;
        reported(error, error_size, [&] { video = new SoftrasterVideo(path, name, webm, width, height, fps); });
        return video;
    },
    [](SoftrasterVideo* video, const uint8_t* rgba, char* error, size_t error_size) { return reported(error, error_size, [&] { video->add(rgba); }); },
    [](SoftrasterVideo* video, char* error, size_t error_size) { return reported(error, error_size, [&] { video->finish(); }); },
    [](SoftrasterVideo* video) { delete video; },
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const SoftrasterVideoApi* softraster_video_api() { return &kApi; }

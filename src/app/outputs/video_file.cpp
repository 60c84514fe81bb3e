#include "app/outputs/video_file.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "io/atomic_file.h"

namespace wobble {

namespace {

// FFmpeg's libraries are loaded at the first video, not linked into the program: they bring
// some forty libraries of their own, whose address space every run would carry, past the
// 200 MiB within which bad input is refused (tests/app/bad_input_catalogue_test.cpp). Each
// library by the major version the headers are of, as a linked program would ask for it.
#define WOBBLE_FFMPEG_LIBRARY(name, major) "lib" #name ".so." AV_STRINGIFY(major)
// clang-format off
#define WOBBLE_AVUTIL(f)                                                                     \
  f(av_strerror) f(av_d2q) f(av_dict_set) f(av_dict_free) f(av_frame_alloc) f(av_frame_free) \
  f(av_frame_get_buffer) f(av_frame_make_writable) f(av_log_set_level)
#define WOBBLE_AVCODEC(f)                                                            \
  f(avcodec_find_encoder_by_name) f(avcodec_alloc_context3) f(avcodec_free_context)  \
  f(avcodec_open2) f(avcodec_parameters_from_context) f(avcodec_send_frame)          \
  f(avcodec_receive_packet) f(av_packet_alloc) f(av_packet_free) f(av_packet_rescale_ts)
#define WOBBLE_AVFORMAT(f)                                                                   \
  f(avformat_alloc_output_context2) f(avformat_new_stream) f(avformat_write_header)          \
  f(avformat_free_context) f(av_interleaved_write_frame) f(av_write_trailer) f(avio_open)    \
  f(avio_closep)
#define WOBBLE_SWSCALE(f)                                                                  \
  f(sws_getCachedContext) f(sws_getCoefficients) f(sws_setColorspaceDetails) f(sws_scale) \
  f(sws_freeContext)
// clang-format on

struct Ffmpeg {
#define WOBBLE_POINTER(name) decltype(&::name) name = nullptr;
  WOBBLE_AVUTIL(WOBBLE_POINTER)
  WOBBLE_AVCODEC(WOBBLE_POINTER)
  WOBBLE_AVFORMAT(WOBBLE_POINTER)
  WOBBLE_SWSCALE(WOBBLE_POINTER)
#undef WOBBLE_POINTER
  std::string error;  // why they could not be loaded; empty when they were
};

Ffmpeg load_ffmpeg() {
  Ffmpeg ffmpeg;
  const auto open = [&](const char* library) -> void* {
    void* handle = dlopen(library, RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr && ffmpeg.error.empty()) {
      ffmpeg.error = std::string("cannot load FFmpeg's ") + library +
                     " (Debian: libavcodec-dev, libavformat-dev, libavutil-dev, libswscale-dev)";
    }
    return handle;
  };
  const auto find = [&](void* handle, auto& pointer, const char* name) {
    if (handle != nullptr)
      pointer = reinterpret_cast<std::decay_t<decltype(pointer)>>(dlsym(handle, name));
    if (pointer == nullptr && ffmpeg.error.empty())
      ffmpeg.error = std::string("FFmpeg lacks ") + name;
  };
#define WOBBLE_FIND(name) find(library, ffmpeg.name, #name);
  void* library = open(WOBBLE_FFMPEG_LIBRARY(avutil, LIBAVUTIL_VERSION_MAJOR));
  WOBBLE_AVUTIL(WOBBLE_FIND)
  library = open(WOBBLE_FFMPEG_LIBRARY(avcodec, LIBAVCODEC_VERSION_MAJOR));
  WOBBLE_AVCODEC(WOBBLE_FIND)
  library = open(WOBBLE_FFMPEG_LIBRARY(avformat, LIBAVFORMAT_VERSION_MAJOR));
  WOBBLE_AVFORMAT(WOBBLE_FIND)
  library = open(WOBBLE_FFMPEG_LIBRARY(swscale, LIBSWSCALE_VERSION_MAJOR));
  WOBBLE_SWSCALE(WOBBLE_FIND)
#undef WOBBLE_FIND
  return ffmpeg;  // the libraries stay loaded for the program's life
}

// The functions, loaded at the first call.
const Ffmpeg& ff() {
  static const Ffmpeg ffmpeg = load_ffmpeg();
  return ffmpeg;
}

std::string ffmpeg_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  ff().av_strerror(code, text, sizeof text);
  return text;
}

// The time base: 1/N s when dt is 1/N to within a thousandth (dt = 0.016667 gives 60 frames a
// second, not 16667/1000000), else dt itself as a fraction.
AVRational tick_of(double dt) {
  if (!(dt > 0.0)) return AVRational{1, 60};
  const double rate = std::round(1.0 / dt);
  if (rate >= 1.0 && rate <= 100000.0 && std::abs(rate * dt - 1.0) < 1e-3) {
    return AVRational{1, static_cast<int>(rate)};
  }
  return ff().av_d2q(dt, 100000);
}

}  // namespace

struct VideoFile::Encoder {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scale = nullptr;
  AVRational tick{1, 60};
  double origin = 0.0;        // simulated time of pts 0 (s)
  double last_seconds = 0.0;  // the last frame's simulated time (s)
  int64_t last_pts = -1;

  // Everything up to the container's header, for frames of width x height (even).
  void open(const std::string& path, VideoFormat video, int width, int height, double dt);
  // Sends `sent` (nullptr: the end) and writes every packet the encoder has ready.
  void encode(AVFrame* sent, const std::string& path);

  ~Encoder() {
    if (!ff().error.empty()) return;  // nothing was made
    ff().sws_freeContext(scale);
    ff().av_packet_free(&packet);
    ff().av_frame_free(&frame);
    ff().avcodec_free_context(&codec);
    if (format != nullptr && format->pb != nullptr) ff().avio_closep(&format->pb);
    ff().avformat_free_context(format);
  }
};

void VideoFile::Encoder::open(const std::string& path, VideoFormat video, int width, int height,
                              double dt) {
  if (width < 2 || height < 2) {
    throw OutputError(path + ": a frame of " + std::to_string(width) + "x" +
                      std::to_string(height) + " pixels is too small for a video");
  }
  if (!ff().error.empty()) throw OutputError(path + ": " + ff().error);
  // FFmpeg's own log (the encoder's statistics, its view of an error) stays off the terminal:
  // an error is reported once, on one line, by what catches the OutputError.
  ff().av_log_set_level(AV_LOG_QUIET);
  const bool webm = video == VideoFormat::webm;
  const AVCodec* encoder = ff().avcodec_find_encoder_by_name(webm ? "libvpx-vp9" : "libx264");
  if (encoder == nullptr) {
    throw OutputError(path + ": this FFmpeg has no " +
                      (webm ? "VP9 (libvpx-vp9)" : "H.264 (libx264)") + " encoder");
  }
  int result =
      ff().avformat_alloc_output_context2(&format, nullptr, webm ? "webm" : "mp4", path.c_str());
  if (result < 0) throw OutputError(path + ": " + ffmpeg_error(result));
  stream = ff().avformat_new_stream(format, nullptr);
  codec = ff().avcodec_alloc_context3(encoder);
  frame = ff().av_frame_alloc();
  packet = ff().av_packet_alloc();
  if (stream == nullptr || codec == nullptr || frame == nullptr || packet == nullptr) {
    throw OutputError(path + ": out of memory for the video encoder");
  }

  tick = tick_of(dt);
  codec->width = width;
  codec->height = height;
  codec->pix_fmt = AV_PIX_FMT_YUV420P;
  codec->time_base = tick;
  codec->framerate = AVRational{tick.den, tick.num};
  // A key frame every two seconds: a player seeks without decoding far.
  codec->gop_size = std::max(1, static_cast<int>(std::lround(2.0 / av_q2d(tick))));
  codec->color_range = AVCOL_RANGE_MPEG;
  codec->colorspace = AVCOL_SPC_BT709;
  codec->color_primaries = AVCOL_PRI_BT709;
  codec->color_trc = AVCOL_TRC_BT709;
  codec->thread_count = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
  if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = nullptr;
  if (webm) {
    // Real-time speed; constant quality (no bit rate aim), which keeps a mostly still
    // background small. docs/command-line.md has sizes and times.
    ff().av_dict_set(&options, "deadline", "realtime", 0);
    ff().av_dict_set(&options, "cpu-used", "8", 0);
    ff().av_dict_set(&options, "row-mt", "1", 0);
    ff().av_dict_set(&options, "crf", "28", 0);
    ff().av_dict_set(&options, "b", "0", 0);
  } else {
    ff().av_dict_set(&options, "preset", "veryfast", 0);
    ff().av_dict_set(&options, "crf", "20", 0);
  }
  result = ff().avcodec_open2(codec, encoder, &options);
  ff().av_dict_free(&options);
  if (result < 0) throw OutputError(path + ": cannot start the encoder: " + ffmpeg_error(result));
  result = ff().avcodec_parameters_from_context(stream->codecpar, codec);
  if (result < 0) throw OutputError(path + ": " + ffmpeg_error(result));
  stream->time_base = tick;
  stream->avg_frame_rate = codec->framerate;

  frame->format = codec->pix_fmt;
  frame->width = width;
  frame->height = height;
  result = ff().av_frame_get_buffer(frame, 0);
  if (result < 0) throw OutputError(path + ": " + ffmpeg_error(result));

  result = ff().avio_open(&format->pb, path.c_str(), AVIO_FLAG_WRITE);
  if (result < 0) throw OutputError(path + ": cannot write: " + ffmpeg_error(result));
  AVDictionary* muxer_options = nullptr;
  // The index (moov) before the frames, so that a browser plays while it downloads.
  if (!webm) ff().av_dict_set(&muxer_options, "movflags", "+faststart", 0);
  // WebM's clusters reach the disk a second at a time, so a run killed by a signal (which
  // completes nothing) still leaves a file that plays up to the last second.
  if (webm) {
    ff().av_dict_set(&muxer_options, "cluster_time_limit", "1000", 0);
    ff().av_dict_set(&muxer_options, "flush_packets", "1", 0);
  }
  result = ff().avformat_write_header(format, &muxer_options);
  ff().av_dict_free(&muxer_options);
  if (result < 0) throw OutputError(path + ": cannot write: " + ffmpeg_error(result));
}

void VideoFile::Encoder::encode(AVFrame* sent, const std::string& path) {
  int result = ff().avcodec_send_frame(codec, sent);
  if (result < 0) throw OutputError(path + ": cannot encode a frame: " + ffmpeg_error(result));
  while ((result = ff().avcodec_receive_packet(codec, packet)) >= 0) {
    // The last frame lasts a tick, so that N frames last N ticks.
    if (packet->duration == 0) packet->duration = 1;
    ff().av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    result = ff().av_interleaved_write_frame(format, packet);  // takes the packet's data
    if (result < 0) throw OutputError(path + ": cannot write: " + ffmpeg_error(result));
    if (format->pb->error < 0)
      throw OutputError(path + ": cannot write: " + ffmpeg_error(format->pb->error));
  }
  if (result != AVERROR(EAGAIN) && result != AVERROR_EOF)
    throw OutputError(path + ": cannot encode a frame: " + ffmpeg_error(result));
}

VideoFile::VideoFile(std::string path, VideoFormat format)
    : path_(std::move(path)), format_(format) {}

VideoFile::~VideoFile() {
  // An error is ending the run: keep what was recorded as a complete file if the disk lets us.
  try {
    finish();
  } catch (...) {
  }
}

void VideoFile::write(const RgbaImage& image, const FrameTime& time) {
  if (finished_) throw OutputError(path_ + ": the video was already finished");
  const double seconds = time.dt > 0.0 ? time.seconds : static_cast<double>(frames_) / 60.0;
  if (!encoder_) {
    auto opened = std::make_unique<Encoder>();
    opened->open(path_, format_, image.width & ~1, image.height & ~1, time.dt);
    opened->origin = seconds;
    encoder_ = std::move(opened);
  }
  Encoder& encoder = *encoder_;
  const double tick = av_q2d(encoder.tick);
  int64_t pts = std::llround((seconds - encoder.origin) / tick);
  if (pts <= encoder.last_pts) {
    if (seconds >= encoder.last_seconds) return;  // within the last frame's tick
    // Back in time (a reset): carry on one tick after the last frame.
    encoder.origin = seconds - static_cast<double>(encoder.last_pts + 1) * tick;
    pts = encoder.last_pts + 1;
  }

  // The image's even part, scaled only when its size is not the video's (a resized window).
  const int width = image.width & ~1, height = image.height & ~1;
  if (width < 2 || height < 2) {
    throw OutputError(path_ + ": a " + std::to_string(image.width) + "x" +
                      std::to_string(image.height) + " frame is too small for a video");
  }
  encoder.scale = ff().sws_getCachedContext(
      encoder.scale, width, height, AV_PIX_FMT_RGBA, encoder.codec->width, encoder.codec->height,
      AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
  if (encoder.scale == nullptr) throw OutputError(path_ + ": cannot convert the frame to yuv420p");
  // Full-range RGB to limited-range BT.709, as the stream is tagged.
  const int* coefficients = ff().sws_getCoefficients(SWS_CS_ITU709);
  ff().sws_setColorspaceDetails(encoder.scale, coefficients, 1, coefficients, 0, 0, 1 << 16,
                                1 << 16);
  int result = ff().av_frame_make_writable(encoder.frame);
  if (result < 0) throw OutputError(path_ + ": " + ffmpeg_error(result));
  const uint8_t* source[1] = {image.pixels.data()};
  const int source_stride[1] = {4 * image.width};
  ff().sws_scale(encoder.scale, source, source_stride, 0, height, encoder.frame->data,
                 encoder.frame->linesize);
  encoder.frame->pts = pts;
  encoder.encode(encoder.frame, path_);
  encoder.last_pts = pts;
  encoder.last_seconds = seconds;
  ++frames_;
}

void VideoFile::finish() {
  if (finished_) return;
  finished_ = true;
  if (!encoder_) return;  // no frame: no file
  std::unique_ptr<Encoder> encoder = std::move(encoder_);
  // The container is completed even when the encoder's last frames fail, so that the frames
  // already written stay playable; the first error is reported.
  std::string error;
  try {
    encoder->encode(nullptr, path_);
  } catch (const OutputError& failure) {
    error = failure.what();
  }
  int result = ff().av_write_trailer(encoder->format);
  if (result < 0 && error.empty())
    error = path_ + ": cannot finish the video: " + ffmpeg_error(result);
  result = ff().avio_closep(&encoder->format->pb);
  if (result < 0 && error.empty())
    error = path_ + ": cannot finish the video: " + ffmpeg_error(result);
  if (!error.empty()) throw OutputError(error);
}

}  // namespace wobble

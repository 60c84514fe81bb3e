// --record FILE.webm / FILE.mp4 and VideoFile: each video is decoded back with FFmpeg's own
// libraries and compared with what was recorded: the number of frames, the size, the time of
// each frame, and the pixels against the PNG frames of the same run.
#include "app/outputs/video_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>

#include "../run_wobble.h"
#include "app/outputs/image_outputs.h"
#include "io/atomic_file.h"
#include "sim/input_error.h"

namespace {

using wobble::testing::Result;
using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

// A video decoded: its frames as RGBA, each frame's time, and the container's duration.
struct DecodedVideo {
  std::string codec;
  int width = 0, height = 0;
  std::vector<wobble::RgbaImage> frames;
  std::vector<double> seconds;
  double duration = 0.0;  // s
};

DecodedVideo decode(const std::string& path) {
  DecodedVideo video;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
    ADD_FAILURE() << "cannot open " << path;
    return video;
  }
  std::unique_ptr<AVFormatContext*, void (*)(AVFormatContext**)> format_owner(&format,
                                                                              avformat_close_input);
  EXPECT_GE(avformat_find_stream_info(format, nullptr), 0);
  const AVCodec* decoder = nullptr;
  const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (index < 0 || decoder == nullptr) {
    ADD_FAILURE() << "no video stream in " << path;
    return video;
  }
  const AVStream* stream = format->streams[index];
  video.codec = decoder->name;
  video.duration = format->duration > 0 ? static_cast<double>(format->duration) / AV_TIME_BASE : 0;
  AVCodecContext* codec = avcodec_alloc_context3(decoder);
  avcodec_parameters_to_context(codec, stream->codecpar);
  EXPECT_EQ(avcodec_open2(codec, decoder, nullptr), 0);
  video.width = codec->width;
  video.height = codec->height;
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* scale = nullptr;
  auto take_frames = [&] {
    while (avcodec_receive_frame(codec, frame) >= 0) {
      scale = sws_getCachedContext(
          scale, frame->width, frame->height, static_cast<AVPixelFormat>(frame->format),
          frame->width, frame->height, AV_PIX_FMT_RGBA, SWS_BICUBIC, nullptr, nullptr, nullptr);
      const int* coefficients = sws_getCoefficients(SWS_CS_ITU709);
      sws_setColorspaceDetails(scale, coefficients, 0, coefficients, 1, 0, 1 << 16, 1 << 16);
      wobble::RgbaImage image;
      image.width = frame->width;
      image.height = frame->height;
      image.pixels.resize(4 * static_cast<std::size_t>(image.width) * image.height);
      uint8_t* target[1] = {image.pixels.data()};
      const int stride[1] = {4 * image.width};
      sws_scale(scale, frame->data, frame->linesize, 0, frame->height, target, stride);
      video.frames.push_back(std::move(image));
      video.seconds.push_back(static_cast<double>(frame->best_effort_timestamp) *
                              av_q2d(stream->time_base));
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == index) {
      avcodec_send_packet(codec, packet);
      take_frames();
    }
    av_packet_unref(packet);
  }
  avcodec_send_packet(codec, nullptr);
  take_frames();
  sws_freeContext(scale);
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&codec);
  return video;
}

// Peak signal-to-noise ratio of `b` against `a` over R, G and B (dB), on a's size cropped to
// b's (the video's even size).
double psnr(const wobble::RgbaImage& a, const wobble::RgbaImage& b) {
  double squares = 0.0;
  long count = 0;
  for (int y = 0; y < b.height; ++y) {
    for (int x = 0; x < b.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double d = static_cast<double>(a.pixel(x, y)[c]) - b.pixel(x, y)[c];
        squares += d * d;
        ++count;
      }
    }
  }
  if (squares == 0.0) return 99.0;
  return 10.0 * std::log10(255.0 * 255.0 / (squares / static_cast<double>(count)));
}

// A picture that changes with `frame`: a gradient and a bright square moving right.
wobble::RgbaImage moving_square(int width, int height, int frame) {
  wobble::RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      unsigned char* p = image.pixels.data() + 4 * (y * width + x);
      const bool square = x >= 2 * frame && x < 2 * frame + 20 && y >= 20 && y < 40;
      p[0] = square ? 240 : static_cast<unsigned char>(40 + x);
      p[1] = square ? 220 : static_cast<unsigned char>(30 + y);
      p[2] = square ? 40 : 120;
      p[3] = 255;
    }
  }
  return image;
}

std::string file_bytes(const std::string& path) {
  return wobble::testing::read_text(path);
}

class VideoFormats : public ::testing::TestWithParam<wobble::VideoFormat> {};

// Odd sides lose their last column and bottom row; each frame lies at its time, so N frames of
// dt last N dt; the pixels are the pictures given.
TEST_P(VideoFormats, FramesKeepTheirTimesAndPixelsAndOddSidesAreCropped) {
  TemporaryFolder folder;
  const std::string path = folder.file(std::string("a") + wobble::video_extension(GetParam()));
  const double dt = 0.01;
  std::vector<wobble::RgbaImage> written;
  {
    wobble::VideoFile video(path, GetParam());
    for (int frame = 0; frame < 30; ++frame) {
      written.push_back(moving_square(161, 91, frame));
      video.write(written.back(), wobble::FrameTime{5.0 + (frame + 1) * dt, dt});
    }
    video.finish();
    EXPECT_EQ(video.frames(), 30);
  }
  const DecodedVideo decoded = decode(path);
  EXPECT_EQ(decoded.codec, GetParam() == wobble::VideoFormat::webm ? "vp9" : "h264");
  EXPECT_EQ(decoded.width, 160);
  EXPECT_EQ(decoded.height, 90);
  ASSERT_EQ(decoded.frames.size(), 30u);
  for (std::size_t i = 0; i < decoded.frames.size(); ++i) {
    // The first frame at 0; a millisecond is WebM's resolution.
    EXPECT_NEAR(decoded.seconds[i], static_cast<double>(i) * dt, 1e-3) << "frame " << i;
    EXPECT_GT(psnr(written[i], decoded.frames[i]), 30.0) << "frame " << i;
  }
  EXPECT_NEAR(decoded.duration, 30 * dt, 1.5e-3);
  // A wrong frame does not match: the comparison can fail.
  EXPECT_LT(psnr(written[0], decoded.frames[29]), 25.0);
}

// A reset sends the simulated time back: the frames after it follow on, one tick later.
TEST_P(VideoFormats, TimeGoingBackContinuesTheVideo) {
  TemporaryFolder folder;
  const std::string path = folder.file(std::string("a") + wobble::video_extension(GetParam()));
  {
    wobble::VideoFile video(path, GetParam());
    const double times[] = {1.0, 1.5, 2.0, 2.0, 0.0, 0.5};  // 2.0 twice: one frame
    for (int frame = 0; frame < 6; ++frame)
      video.write(moving_square(64, 48, frame), wobble::FrameTime{times[frame], 0.5});
    EXPECT_EQ(video.frames(), 5);
  }  // completed by the destructor, as when an error ends a run
  const DecodedVideo decoded = decode(path);
  ASSERT_EQ(decoded.frames.size(), 5u);
  const double expected[] = {0.0, 0.5, 1.0, 1.5, 2.0};
  for (int i = 0; i < 5; ++i)
    EXPECT_NEAR(decoded.seconds[i], expected[i], 1e-3) << "frame " << i;
}

INSTANTIATE_TEST_SUITE_P(WebmAndMp4, VideoFormats,
                         ::testing::Values(wobble::VideoFormat::webm, wobble::VideoFormat::mp4),
                         [](const auto& info) {
                           return std::string(info.param == wobble::VideoFormat::webm ? "WebM"
                                                                                      : "Mp4");
                         });

TEST(VideoFile, Mp4HasItsIndexBeforeTheFrames) {
  TemporaryFolder folder;
  const std::string path = folder.file("a.mp4");
  wobble::VideoFile video(path, wobble::VideoFormat::mp4);
  for (int frame = 0; frame < 5; ++frame)
    video.write(moving_square(64, 48, frame), wobble::FrameTime{frame / 60.0, 1 / 60.0});
  video.finish();
  const std::string bytes = file_bytes(path);
  ASSERT_NE(bytes.find("moov"), std::string::npos);
  ASSERT_NE(bytes.find("mdat"), std::string::npos);
  EXPECT_LT(bytes.find("moov"), bytes.find("mdat")) << "faststart: a browser plays at once";
}

// The same run recorded as PNG frames and as a video: the video has every frame rendered, at
// the simulation's rate, and its pictures are the PNGs.
TEST_P(VideoFormats, RecordFileIsTheRunsFramesAtTheSimulationsRate) {
  TemporaryFolder folder;
  const std::string run = "'" WOBBLE_ASSETS_DIR
                          "/flag.json' --headless --frames 30 --width 161 "
                          "--height 90 --record ";
  const std::string video_path =
      folder.file(std::string("flag") + wobble::video_extension(GetParam()));
  Result result = run_wobble(run + "'" + folder.file("frames") + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  result = run_wobble(run + "'" + video_path + "'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err.find("libx264"), std::string::npos) << "FFmpeg's log stays quiet";

  const DecodedVideo decoded = decode(video_path);
  EXPECT_EQ(decoded.width, 160) << "161 is odd: the last column goes";
  EXPECT_EQ(decoded.height, 90);
  ASSERT_EQ(decoded.frames.size(), 30u);
  const double dt = 0.016667;  // flag.json's
  EXPECT_NEAR(decoded.duration, 30 * dt, 2e-3);
  for (std::size_t i = 0; i < decoded.frames.size(); ++i) {
    EXPECT_NEAR(decoded.seconds[i], static_cast<double>(i) * dt, 1.5e-3) << "frame " << i;
    const wobble::RgbaImage png = wobble::read_png(
        wobble::ImageOutputs::frame_file(folder.file("frames"), static_cast<long>(i) + 1));
    EXPECT_GT(psnr(png, decoded.frames[i]), 30.0) << "frame " << i + 1;
  }
}

TEST(RecordVideo, OtherImageAndVideoFilesAreRefusedBeforeAnyWork) {
  TemporaryFolder folder;
  for (const char* name : {"a.gif", "a.webp", "a.avi", "a.MOV"}) {
    const Result result = run_wobble(
        "cloth --headless --frames 2 --width 64 --height 48 --record '" + folder.file(name) + "'");
    EXPECT_EQ(result.exit_code, 2) << name;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find("--record"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find(".webm"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find(".mp4"), std::string::npos) << result.err;
  }
  EXPECT_TRUE(folder.entries().empty()) << "nothing written";
  // A path with no such extension is still a folder of PNG frames.
  const Result result = run_wobble("cloth --headless --frames 2 --width 64 --height 48 --record '" +
                                   folder.file("frames.v2") + "'");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(
      std::filesystem::exists(wobble::ImageOutputs::frame_file(folder.file("frames.v2"), 2)));
  // Refused here too, for the window's and headless runs alike.
  std::ostringstream progress;
  EXPECT_THROW(wobble::ImageOutputs("", folder.file("b.gif"), 1, progress), wobble::InputError);
  EXPECT_THROW(wobble::ImageOutputs("", folder.file("missing/b.webm"), 1, progress),
               wobble::InputError);
}

// A disk that fills up: one line, the run's failure code, no crash.
TEST(RecordVideo, AFullDiskIsOneLineAndNoCrash) {
  TemporaryFolder folder;
  const std::string path = folder.file("full.webm");
  ASSERT_EQ(symlink("/dev/full", path.c_str()), 0);
  const Result result =
      run_wobble("cloth --headless --frames 20 --width 64 --height 48 --record '" + path + "'");
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("full.webm"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("No space left"), std::string::npos) << result.err;
}

}  // namespace

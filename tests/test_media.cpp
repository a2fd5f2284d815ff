// Movies and EXRs (media/): what is written is read back, with FFmpeg's decoders and OpenEXR, and
// compared with what went in.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include "base/error.hpp"
#include "media/exr.hpp"
#include "media/movie.hpp"

namespace cellproj {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("cellproj_media_" + name)).string();
}

// Frame f: eight vertical colour bars (the primaries, their mixes, black and white) and a grey
// square moving right a few pixels a frame, so that the encoder has motion to code.
Rgb8Image test_frame(int width, int height, int f) {
  static const unsigned char bars[8][3] = {{255, 255, 255}, {255, 255, 0}, {0, 255, 255}, {0, 255, 0},
                                           {255, 0, 255},   {255, 0, 0},   {0, 0, 255},   {0, 0, 0}};
  Rgb8Image img{width, height, std::vector<unsigned char>(static_cast<std::size_t>(width) * height * 3)};
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      unsigned char* p = img.pixel(i, j);
      const unsigned char* bar = bars[i * 8 / width];
      const bool square = j >= height / 2 && j < height / 2 + 16 && i >= 4 * f && i < 4 * f + 16;
      for (int k = 0; k < 3; ++k) p[k] = square ? 128 : bar[k];
    }
  return img;
}

// Every frame of a movie decoded to RGB, with FFmpeg's own decoder.
std::vector<Rgb8Image> decode(const std::string& path) {
  AVFormatContext* in = nullptr;
  EXPECT_EQ(avformat_open_input(&in, path.c_str(), nullptr, nullptr), 0);
  EXPECT_GE(avformat_find_stream_info(in, nullptr), 0);
  const int s = av_find_best_stream(in, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  const AVCodec* codec = avcodec_find_decoder(in->streams[s]->codecpar->codec_id);
  AVCodecContext* ctx = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(ctx, in->streams[s]->codecpar);
  EXPECT_EQ(avcodec_open2(ctx, codec, nullptr), 0);
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  std::vector<Rgb8Image> frames;
  const auto receive = [&] {
    while (avcodec_receive_frame(ctx, frame) == 0) {
      Rgb8Image rgb{frame->width, frame->height,
                    std::vector<unsigned char>(static_cast<std::size_t>(frame->width) * frame->height * 3)};
      SwsContext* sws =
          sws_getContext(frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
                         frame->height, AV_PIX_FMT_RGB24, SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
      if (frame->format == AV_PIX_FMT_YUV420P) {  // as the stream says: BT.709, limited range
        const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(sws, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
      }
      uint8_t* planes[1] = {rgb.rgb.data()};
      const int strides[1] = {rgb.width * 3};
      sws_scale(sws, frame->data, frame->linesize, 0, frame->height, planes, strides);
      sws_freeContext(sws);
      frames.push_back(std::move(rgb));
    }
  };
  while (av_read_frame(in, packet) >= 0) {
    if (packet->stream_index == s) {
      avcodec_send_packet(ctx, packet);
      receive();
    }
    av_packet_unref(packet);
  }
  avcodec_send_packet(ctx, nullptr);
  receive();
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&ctx);
  avformat_close_input(&in);
  return frames;
}

// The mean over the picture of the largest channel difference, in [0, 255].
double mean_difference(const Rgb8Image& a, const Rgb8Image& b) {
  double sum = 0.0;
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i) {
      int worst = 0;
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, std::abs(int(a.rgb[(std::size_t(j) * a.width + i) * 3 + k]) -
                                         int(b.rgb[(std::size_t(j) * b.width + i) * 3 + k])));
      sum += worst;
    }
  return sum / (double(a.width) * a.height);
}

void write_movie(const std::string& path, int width, int height, int frames, MovieOptions options = {}) {
  MovieWriter movie(path, options);
  for (int f = 0; f < frames; ++f) movie.add(test_frame(width, height, f));
  movie.finish();
  EXPECT_EQ(movie.frames(), frames);
}

TEST(Movie, FormatByExtension) {
  EXPECT_EQ(movie_format("a/turn.mp4"), MovieFormat::mp4);
  EXPECT_EQ(movie_format("TURN.GIF"), MovieFormat::gif);
  EXPECT_FALSE(movie_format("turn.png"));
  EXPECT_FALSE(movie_format("turn"));
  EXPECT_THROW(MovieWriter("turn.avi"), InputError);
}

TEST(Movie, Mp4DecodesToItsFramesInColourAndCount) {
  const std::string path = temp_path("bars.mp4");
  write_movie(path, 128, 96, 12);
  std::vector<Rgb8Image> frames = decode(path);
  ASSERT_EQ(frames.size(), 12u);
  for (int f : {0, 5, 11}) {
    ASSERT_EQ(frames[f].width, 128);
    ASSERT_EQ(frames[f].height, 96);
    // Swapped channels, full for limited range or BT.601 for BT.709 would be tens of levels off.
    EXPECT_LT(mean_difference(frames[f], test_frame(128, 96, f)), 4.0) << "frame " << f;
    Rgb8Image expected = test_frame(128, 96, f);
    for (int bar = 0; bar < 8; ++bar) {  // each bar's centre, away from chroma's edges
      const unsigned char* got = frames[f].pixel(bar * 16 + 8, 20);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(got[k], expected.pixel(bar * 16 + 8, 20)[k], 6) << "frame " << f << " bar " << bar;
    }
  }
  std::filesystem::remove(path);
}

TEST(Movie, GifDecodesToItsFramesWithAPaletteEach) {
  quiet_ffmpeg_messages();  // palettegen notes each palette
  const std::string path = temp_path("bars.gif");
  write_movie(path, 96, 64, 9, {10.0, 18});
  const std::vector<Rgb8Image> frames = decode(path);
  ASSERT_EQ(frames.size(), 9u);
  for (int f = 0; f < 9; ++f) EXPECT_LT(mean_difference(frames[f], test_frame(96, 64, f)), 2.0) << "frame " << f;
  std::filesystem::remove(path);
}

TEST(Movie, OddSidesArePaddedForH264) {
  const std::string path = temp_path("odd.mp4");
  write_movie(path, 63, 45, 3);
  const std::vector<Rgb8Image> frames = decode(path);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0].width, 64);
  EXPECT_EQ(frames[0].height, 46);
  std::filesystem::remove(path);
}

TEST(Movie, BadFramesAndPathsAreRefusedAndHalfAMovieIsRemoved) {
  const std::string path = temp_path("half.mp4");
  {
    MovieWriter movie(path);
    movie.add(test_frame(64, 48, 0));
    EXPECT_TRUE(std::filesystem::exists(path));
    EXPECT_THROW(movie.add(test_frame(64, 50, 1)), InputError);  // another size
  }                                                              // not finished: removed
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_THROW(MovieWriter(path).finish(), InputError);  // no frame
  EXPECT_THROW(MovieWriter(path, {0.0, 18}), InputError);
  EXPECT_THROW(MovieWriter(path, {24.0, 60}), InputError);
  MovieWriter unwritable(temp_path("no_such_folder/turn.mp4"));
  try {
    unwritable.add(test_frame(64, 48, 0));
    FAIL() << "a movie in a missing folder was opened";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_folder/turn.mp4"), std::string::npos) << e.what();
  }
}

TEST(Exr, FloatsReadBackBitForBit) {
  Image image(7, 5);
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = static_cast<float>(std::sin(0.37 * double(i)) * 0.5 + 0.5) * (i % 4 == 3 ? 1.0f : 0.6f);
  image.rgba[3] = 0.0f, image.rgba[0] = image.rgba[1] = image.rgba[2] = 0.0f;  // a clear pixel
  const std::string path = temp_path("floats.exr");
  write_exr(image, path);
  const Image back = read_exr(path);
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) ASSERT_EQ(back.rgba[i], image.rgba[i]) << "sample " << i;
  std::filesystem::remove(path);
}

TEST(Exr, AStraightAlphaPictureIsPremultipliedAgain) {
  Image image(4, 1);
  const float px[4][4] = {{0.2f, 0.1f, 0.05f, 0.25f}, {0, 0, 0, 0}, {0.5f, 0.5f, 0.5f, 1.0f}, {1e-4f, 0, 0, 2e-4f}};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) image.pixel(i, 0)[k] = px[i][k];
  const Image back = premultiplied(to_display(image, std::nullopt));
  for (std::size_t i = 0; i < image.rgba.size(); ++i) EXPECT_NEAR(back.rgba[i], image.rgba[i], 1e-7) << i;
}

TEST(Exr, ATextFileOrAMissingOneIsAnInputError) {
  const std::string path = temp_path("not.exr");
  std::ofstream(path) << "not an EXR\n";
  EXPECT_THROW(read_exr(path), InputError);
  EXPECT_THROW(read_exr(temp_path("missing.exr")), InputError);
  EXPECT_THROW(write_exr(Image(3, 3), temp_path("no_such_folder/x.exr")), InputError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace cellproj

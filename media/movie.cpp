#include "media/movie.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "base/error.hpp"
#include "base/file_status.hpp"

namespace cellproj {
namespace {

std::string av_message(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// The frame with its odd last column and row repeated: H.264 in yuv420p takes even sides.
Rgb8Image even_sides(const Rgb8Image& frame) {
  Rgb8Image out{frame.width + frame.width % 2, frame.height + frame.height % 2, {}};
  out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  for (int j = 0; j < out.height; ++j)
    for (int i = 0; i < out.width; ++i)
      std::memcpy(out.pixel(i, j),
                  frame.rgb.data() + (static_cast<std::size_t>(std::min(j, frame.height - 1)) * frame.width +
                                      std::min(i, frame.width - 1)) *
                                         3,
                  3);
  return out;
}

}  // namespace

std::optional<MovieFormat> movie_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".mp4") return MovieFormat::mp4;
  if (ext == ".gif") return MovieFormat::gif;
  return std::nullopt;
}

// FFmpeg's objects for one movie: the container, the encoder, and what turns RGB into the encoder's
// pixels (swscale to yuv420p for H.264; for a GIF a filter graph making each frame's palette).
struct MovieWriter::Encoder {
  AVFormatContext* container = nullptr;
  AVStream* stream = nullptr;
  AVCodecContext* codec = nullptr;
  AVFrame* frame = nullptr;  // the encoder's input (H.264) or the filter graph's (GIF)
  AVFrame* filtered = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* to_yuv = nullptr;
  AVFilterGraph* graph = nullptr;
  AVFilterContext *source = nullptr, *sink = nullptr;
  int width = 0, height = 0;  // the frames' (before H.264's padding)
  bool file_opened = false;
  std::string path;

  ~Encoder() {
    sws_freeContext(to_yuv);
    avfilter_graph_free(&graph);
    av_packet_free(&packet);
    av_frame_free(&filtered);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (container && !(container->oformat->flags & AVFMT_NOFILE)) avio_closep(&container->pb);
    avformat_free_context(container);
  }

  void check(int code, const char* what) const {
    if (code < 0) throw InputError(where(path, std::string(what) + ": " + av_message(code)));
  }

  // Every packet the encoder has ready, into the container.
  void drain() {
    for (;;) {
      const int got = avcodec_receive_packet(codec, packet);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, "encoding a frame");
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check(av_interleaved_write_frame(container, packet), "writing a frame");
    }
  }
  void encode(AVFrame* f) {
    check(avcodec_send_frame(codec, f), "encoding a frame");
    drain();
  }
  // Every frame the palette graph has ready, encoded.
  void drain_graph() {
    for (;;) {
      const int got = av_buffersink_get_frame(sink, filtered);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, "making a frame's palette");
      encode(filtered);
      av_frame_unref(filtered);
    }
  }
};

void quiet_ffmpeg_messages() { av_log_set_level(AV_LOG_ERROR); }

MovieWriter::MovieWriter(std::string path, MovieOptions options) : path_(std::move(path)), options_(options) {
  const std::optional<MovieFormat> format = movie_format(path_);
  if (!format) throw InputError(where(path_, "a movie is written as .mp4 (H.264) or .gif"));
  format_ = *format;
  if (!std::isfinite(options_.frames_per_second) || options_.frames_per_second <= 0.0 ||
      options_.frames_per_second > 240.0)
    throw InputError(
        where(path_, "frames per second must be in (0, 240], got " + std::to_string(options_.frames_per_second)));
  if (options_.quality < 0 || options_.quality > 51)
    throw InputError(where(
        path_, "H.264's quality (constant rate factor) must be in 0..51, got " + std::to_string(options_.quality)));
}

MovieWriter::~MovieWriter() {
  if (finished_ || !encoder_) return;
  const bool opened = encoder_->file_opened;
  encoder_.reset();
  std::error_code ignored;
  if (opened) std::filesystem::remove(path_, ignored);  // never half a movie
}

void MovieWriter::add(const Rgb8Image& frame) {
  if (finished_) throw InternalError(where(path_, "a frame added to a finished movie"));
  if (!encoder_) {
    encoder_ = std::make_unique<Encoder>();
    Encoder& e = *encoder_;
    e.path = path_, e.width = frame.width, e.height = frame.height;
    const bool gif = format_ == MovieFormat::gif;
    e.check(avformat_alloc_output_context2(&e.container, nullptr, gif ? "gif" : "mp4", path_.c_str()),
            "opening the movie");
    const AVCodec* codec = gif ? avcodec_find_encoder(AV_CODEC_ID_GIF) : avcodec_find_encoder_by_name("libx264");
    if (!codec && !gif) codec = avcodec_find_encoder(AV_CODEC_ID_H264);
    if (!codec)
      throw ResourceError(where(path_, std::string("this FFmpeg has no ") + (gif ? "GIF" : "H.264") +
                                           " encoder (Debian's libavcodec has both)"));
    e.stream = avformat_new_stream(e.container, nullptr);
    e.codec = avcodec_alloc_context3(codec);
    e.frame = av_frame_alloc(), e.filtered = av_frame_alloc(), e.packet = av_packet_alloc();
    if (!e.stream || !e.codec || !e.frame || !e.filtered || !e.packet)
      throw ResourceError(where(path_, "out of memory opening the movie"));
    const AVRational rate = av_d2q(options_.frames_per_second, 100000);
    e.codec->width = gif ? frame.width : frame.width + frame.width % 2;
    e.codec->height = gif ? frame.height : frame.height + frame.height % 2;
    e.codec->time_base = av_inv_q(rate), e.codec->framerate = rate;
    e.codec->pix_fmt = gif ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
    e.codec->log_level_offset = AV_LOG_VERBOSE - AV_LOG_INFO;  // its statistics are not the user's news
    e.stream->time_base = e.codec->time_base;
    if (!gif) {
      // BT.709, limited range, said in the stream so that players convert back alike.
      e.codec->color_range = AVCOL_RANGE_MPEG, e.codec->colorspace = AVCOL_SPC_BT709;
      e.codec->color_primaries = AVCOL_PRI_BT709, e.codec->color_trc = AVCOL_TRC_BT709;
      av_opt_set(e.codec->priv_data, "preset", "medium", 0);
      av_opt_set_int(e.codec->priv_data, "crf", options_.quality, 0);
    }
    if (e.container->oformat->flags & AVFMT_GLOBALHEADER) e.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    e.check(avcodec_open2(e.codec, codec, nullptr), "opening the encoder");
    e.check(avcodec_parameters_from_context(e.stream->codecpar, e.codec), "opening the movie");
    if (!(e.container->oformat->flags & AVFMT_NOFILE))
      e.check(avio_open(&e.container->pb, path_.c_str(), AVIO_FLAG_WRITE), "cannot be written");
    e.file_opened = true;
    e.check(avformat_write_header(e.container, nullptr), "writing the movie's header");

    if (gif) {
      // A palette of 256 colours made for each frame from its own pixels, then used with dithering.
      e.graph = avfilter_graph_alloc();
      char args[160];
      std::snprintf(args, sizeof args, "video_size=%dx%d:pix_fmt=rgb24:time_base=%d/%d:pixel_aspect=1/1", frame.width,
                    frame.height, e.codec->time_base.num, e.codec->time_base.den);
      e.check(avfilter_graph_create_filter(&e.source, avfilter_get_by_name("buffer"), "in", args, nullptr, e.graph),
              "making the palette filter");
      e.check(
          avfilter_graph_create_filter(&e.sink, avfilter_get_by_name("buffersink"), "out", nullptr, nullptr, e.graph),
          "making the palette filter");
      AVFilterInOut* outputs = avfilter_inout_alloc();
      AVFilterInOut* inputs = avfilter_inout_alloc();
      outputs->name = av_strdup("in"), outputs->filter_ctx = e.source, outputs->pad_idx = 0, outputs->next = nullptr;
      inputs->name = av_strdup("out"), inputs->filter_ctx = e.sink, inputs->pad_idx = 0, inputs->next = nullptr;
      const int parsed = avfilter_graph_parse_ptr(
          e.graph, "split[a][b];[a]palettegen=stats_mode=single[p];[b][p]paletteuse=new=1", &inputs, &outputs, nullptr);
      avfilter_inout_free(&inputs);
      avfilter_inout_free(&outputs);
      e.check(parsed, "making the palette filter");
      e.check(avfilter_graph_config(e.graph, nullptr), "making the palette filter");
    } else {
      e.to_yuv = sws_getContext(e.codec->width, e.codec->height, AV_PIX_FMT_RGB24, e.codec->width, e.codec->height,
                                AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
      if (!e.to_yuv) throw ResourceError(where(path_, "swscale cannot convert RGB to yuv420p"));
      const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
      sws_setColorspaceDetails(e.to_yuv, bt709, /*source full range*/ 1, bt709, /*limited range*/ 0, 0, 1 << 16,
                               1 << 16);
    }
    e.frame->format = gif ? AV_PIX_FMT_RGB24 : AV_PIX_FMT_YUV420P;
    e.frame->width = e.codec->width, e.frame->height = e.codec->height;
    e.check(av_frame_get_buffer(e.frame, 0), "allocating a frame");
  }
  Encoder& e = *encoder_;
  if (frame.width != e.width || frame.height != e.height)
    throw InputError(where(path_, "frame " + std::to_string(frames_ + 1) + " is " + std::to_string(frame.width) + "x" +
                                      std::to_string(frame.height) + ", the movie's frames " + std::to_string(e.width) +
                                      "x" + std::to_string(e.height) + ": every frame must have one size"));
  e.check(av_frame_make_writable(e.frame), "allocating a frame");
  e.frame->pts = frames_;
  if (format_ == MovieFormat::gif) {
    for (int j = 0; j < frame.height; ++j)
      std::memcpy(e.frame->data[0] + static_cast<std::ptrdiff_t>(j) * e.frame->linesize[0],
                  frame.rgb.data() + static_cast<std::size_t>(j) * frame.width * 3,
                  static_cast<std::size_t>(frame.width) * 3);
    e.check(av_buffersrc_add_frame_flags(e.source, e.frame, AV_BUFFERSRC_FLAG_KEEP_REF), "making a frame's palette");
    e.drain_graph();
  } else {
    const Rgb8Image even = frame.width % 2 || frame.height % 2 ? even_sides(frame) : Rgb8Image{};
    const Rgb8Image& rgb = even.rgb.empty() ? frame : even;
    const std::uint8_t* planes[1] = {rgb.rgb.data()};
    const int strides[1] = {rgb.width * 3};
    sws_scale(e.to_yuv, planes, strides, 0, rgb.height, e.frame->data, e.frame->linesize);
    e.encode(e.frame);
  }
  ++frames_;
}

void MovieWriter::finish() {
  if (finished_) return;
  if (!encoder_) throw InputError(where(path_, "a movie needs at least one frame"));
  Encoder& e = *encoder_;
  if (format_ == MovieFormat::gif) {
    e.check(av_buffersrc_add_frame_flags(e.source, nullptr, 0), "making a frame's palette");
    e.drain_graph();
  }
  e.encode(nullptr);
  e.check(av_write_trailer(e.container), "writing the movie's index");
  if (!(e.container->oformat->flags & AVFMT_NOFILE)) e.check(avio_closep(&e.container->pb), "closing the movie");
  finished_ = true;
  encoder_.reset();
}

}  // namespace cellproj

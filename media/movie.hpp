#pragma once
// A movie written frame by frame through FFmpeg's libraries: H.264 in MP4 (yuv420p, BT.709, for
// every player and slide), or an animated GIF with a palette made for each frame. Each frame is
// encoded as it is added, so memory does not grow with the frame count.
#include <memory>
#include <optional>
#include <string>

#include "view/image.hpp"

namespace cellproj {

enum class MovieFormat { mp4, gif };

// The movie format a path's extension names (.mp4, .gif, any case), or none.
std::optional<MovieFormat> movie_format(const std::string& path);

struct MovieOptions {
  double frames_per_second = 24.0;  // in (0, 240]; a GIF's delay is in hundredths of a second
  int quality = 18;                 // H.264's constant rate factor: 0 lossless .. 51 worst (18: near transparent)
};

// FFmpeg's own messages below errors silenced (its filters' notes on each palette). FFmpeg's log
// level belongs to the process, so only a front end calls this: the CLI at its start, Python when
// a movie is made.
void quiet_ffmpeg_messages();

class MovieWriter {
 public:
  // Nothing is opened until the first frame, which fixes the size. InputError for a path that
  // names no movie format or an option out of range.
  MovieWriter(std::string path, MovieOptions options = {});
  // A movie not finished (an error on the way) is closed and its file removed: never half a movie.
  ~MovieWriter();
  MovieWriter(const MovieWriter&) = delete;
  MovieWriter& operator=(const MovieWriter&) = delete;

  // The next frame. Every frame must have the first one's size (InputError otherwise); H.264's odd
  // width or height is padded by a pixel of the frame's own edge. InputError naming the path if the
  // file cannot be written; ResourceError if this FFmpeg has no encoder for the format.
  void add(const Rgb8Image& frame);
  // Flushes the encoder and writes the container's index: the movie is complete. InputError if no
  // frame was added.
  void finish();

  int frames() const { return frames_; }
  const std::string& path() const { return path_; }

 private:
  struct Encoder;
  std::string path_;
  MovieFormat format_;
  MovieOptions options_;
  int frames_ = 0;
  bool finished_ = false;
  std::unique_ptr<Encoder> encoder_;
};

}  // namespace cellproj

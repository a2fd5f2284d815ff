#include "mesh/time_series.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include "base/error.hpp"
#include "base/timing.hpp"
#include "mesh/field_choice.hpp"

namespace cellproj {

SeriesPosition locate(const TimeSeries& s, double t) {
  const double first = s.frames.front().time, last = s.frames.back().time;
  if (!(t >= first && t <= last))
    throw InputError(where(s.source, "time " + std::to_string(t) + " is outside the series' times [" +
                                         std::to_string(first) + ", " + std::to_string(last) + "]"));
  const auto after = std::lower_bound(s.frames.begin(), s.frames.end(), t,
                                      [](const KeyFrame& f, double time) { return f.time < time; });
  const std::size_t k = static_cast<std::size_t>(after - s.frames.begin());
  if (after->time == t) return {k, k, 0.0};
  return {k - 1, k, (t - s.frames[k - 1].time) / (after->time - s.frames[k - 1].time)};
}

SeriesPlayer::SeriesPlayer(TimeSeries series, std::string field, KeyFrameReader read)
    : series_(std::move(series)), field_(std::move(field)), read_(std::move(read)) {
  if (!read_) throw InternalError("SeriesPlayer: no key frame reader");
  if (series_.frames.empty()) throw InputError(where(series_.source, "names no key frame"));
}

const SeriesPlayer::Held& SeriesPlayer::hold(std::size_t index, std::size_t keep) {
  for (const Held& h : held_)
    if (h.index == index) return h;
  // Evict a key frame other than `keep`: the one further from `index`, which a playback left behind.
  const auto distance = [&](const Held& h) {
    return h.index == kNone ? ~std::size_t(0) : h.index > index ? h.index - index : index - h.index;
  };
  Held& slot = held_[0].index == keep                     ? held_[1]
               : held_[1].index == keep                   ? held_[0]
               : distance(held_[0]) >= distance(held_[1]) ? held_[0]
                                                          : held_[1];
  const KeyFrame& kf = series_.frames[index];
  const auto start = std::chrono::steady_clock::now();
  LoadedMesh loaded = read_(kf);
  Mesh& m = loaded.mesh;
  const std::string what =
      "key frame " + std::to_string(index) + " (time " + std::to_string(kf.time) + ") of " + series_.source;
  if (reads_ == 0) {
    field_ = choose_field(m, field_).name;  // the scalar every key frame gives (a vector's component, ...)
    first_report_ = loaded.report;
    cells_.source = series_.source;
    cells_.connectivity = std::move(m.connectivity);
    cells_.offsets = std::move(m.offsets);
    cells_.types = std::move(m.types);
    first_points_ = std::make_shared<const std::vector<double>>(std::move(m.points));
  } else {
    if (m.types != cells_.types || m.offsets != cells_.offsets || m.connectivity != cells_.connectivity ||
        m.points.size() != first_points_->size())
      throw InputError(where(kf.path, what +
                                          ": its cells differ from the first key frame's; the key frames of a "
                                          "series must share their points and cells (only their values may change)"));
  }
  slot.index = index;
  if (reads_ == 0 || m.points == *first_points_) {
    slot.points = first_points_;
  } else {
    slot.points = std::make_shared<const std::vector<double>>(std::move(m.points));
    points_move_ = true;
  }
  slot.field = std::move(select_field(m, field_).values);
  ++reads_;
  read_seconds_ += seconds_since(start);
  return slot;
}

SeriesFrame SeriesPlayer::frame_at(double t) {
  SeriesFrame out;
  out.time = t;
  out.position = locate(series_, t);
  const SeriesPosition& p = out.position;
  const Held& a = hold(p.before, p.after);
  if (p.before == p.after) {  // exactly a key frame
    out.points = a.points;
    out.field = a.field;
    return out;
  }
  const Held& b = hold(p.after, p.before);
  const double w = p.weight;
  out.field.resize(a.field.size());
  for (std::size_t i = 0; i < out.field.size(); ++i) out.field[i] = (1.0 - w) * a.field[i] + w * b.field[i];
  if (a.points == b.points) {
    out.points = a.points;
  } else {
    auto points = std::make_shared<std::vector<double>>(a.points->size());
    for (std::size_t i = 0; i < points->size(); ++i) (*points)[i] = (1.0 - w) * (*a.points)[i] + w * (*b.points)[i];
    out.points = std::move(points);
  }
  return out;
}

MeshView SeriesPlayer::view(const SeriesFrame& frame) const {
  MeshView v = cells_.view();
  v.points = frame.points->data();
  v.n_points = static_cast<std::int64_t>(frame.points->size() / 3);
  return v;
}

}  // namespace cellproj

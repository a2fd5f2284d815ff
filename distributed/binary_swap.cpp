#include "distributed/binary_swap.hpp"

#include <algorithm>
#include <array>
#include <chrono>

#include <mpi.h>

#include "base/error.hpp"
#include "composite/fragment.hpp"

namespace cellproj {
namespace {

ScreenBox rows_of(const ScreenBox& b, int y0, int y1) {
  ScreenBox r{b.x0, std::max(b.y0, y0), b.x1, std::min(b.y1, y1)};
  return r.empty() ? ScreenBox{} : r;
}

ScreenBox join(const ScreenBox& a, const ScreenBox& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

std::vector<float> pack(const Image& image, const ScreenBox& b) {
  std::vector<float> data(b.empty() ? 0 : static_cast<std::size_t>(b.width()) * b.height() * 4);
  for (int j = b.y0; j < b.y1; ++j)
    std::copy(image.pixel(b.x0, j), image.pixel(b.x1, j),
              data.data() + static_cast<std::size_t>(j - b.y0) * b.width() * 4);
  return data;
}

// The pixels of `data` (box b) in front of (nearer = true) or behind what `image` holds.
void blend(Image& image, const ScreenBox& b, const std::vector<float>& data, bool nearer) {
  for (int j = b.y0; j < b.y1; ++j)
    for (int i = b.x0; i < b.x1; ++i) {
      const float* src = data.data() + (static_cast<std::size_t>(j - b.y0) * b.width() + (i - b.x0)) * 4;
      nearer ? over(image.pixel(i, j), src) : under(image.pixel(i, j), src);
    }
}

// Messages: the box (4 ints), then its pixels.
class Exchange {
 public:
  explicit Exchange(TrafficStats& stats) : stats_(stats) {}

  void send(const Image& image, const ScreenBox& b, int to) {
    const std::array<int, 4> box{b.x0, b.y0, b.x1, b.y1};
    const std::vector<float> data = pack(image, b);
    MPI_Send(box.data(), 4, MPI_INT, to, 0, MPI_COMM_WORLD);
    MPI_Send(data.data(), static_cast<int>(data.size()), MPI_FLOAT, to, 1, MPI_COMM_WORLD);
    stats_.bytes_sent += sizeof box + data.size() * sizeof(float);
  }

  ScreenBox receive(int from, std::vector<float>& data) {
    std::array<int, 4> box{};
    MPI_Recv(box.data(), 4, MPI_INT, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const ScreenBox b{box[0], box[1], box[2], box[3]};
    data.resize(b.empty() ? 0 : static_cast<std::size_t>(b.width()) * b.height() * 4);
    MPI_Recv(data.data(), static_cast<int>(data.size()), MPI_FLOAT, from, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    stats_.bytes_received += sizeof box + data.size() * sizeof(float);
    return b;
  }

  // Both directions at once (a partner sends while it receives: no deadlock on large messages).
  ScreenBox swap(const Image& image, const ScreenBox& give, int partner, std::vector<float>& data) {
    const std::array<int, 4> out{give.x0, give.y0, give.x1, give.y1};
    std::array<int, 4> in{};
    MPI_Sendrecv(out.data(), 4, MPI_INT, partner, 2, in.data(), 4, MPI_INT, partner, 2, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
    const ScreenBox b{in[0], in[1], in[2], in[3]};
    const std::vector<float> sent = pack(image, give);
    data.resize(b.empty() ? 0 : static_cast<std::size_t>(b.width()) * b.height() * 4);
    MPI_Sendrecv(sent.data(), static_cast<int>(sent.size()), MPI_FLOAT, partner, 3, data.data(),
                 static_cast<int>(data.size()), MPI_FLOAT, partner, 3, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    stats_.bytes_sent += sizeof out + sent.size() * sizeof(float);
    stats_.bytes_received += sizeof in + data.size() * sizeof(float);
    return b;
  }

 private:
  TrafficStats& stats_;
};

}  // namespace

TrafficStats composite_binary_swap(const Communicator& comm, Image& image, ScreenBox covered,
                                   const std::vector<int>& back_to_front) {
  TrafficStats stats;
  if (!comm.mpi || comm.size == 1) return stats;
  const auto t0 = std::chrono::steady_clock::now();
  const int P = comm.size;
  if (static_cast<int>(back_to_front.size()) != P) throw InternalError("binary swap: the order must list every rank");
  const int pos =
      static_cast<int>(std::find(back_to_front.begin(), back_to_front.end(), comm.rank) - back_to_front.begin());
  int P2 = 1;
  while (2 * P2 <= P) P2 *= 2;
  const int extra = P - P2;
  // Participant q's rank: the first 2 * extra positions pair up (the farther of each pair keeps it).
  const auto rank_of = [&](int q) { return q < extra ? back_to_front[2 * q] : back_to_front[q + extra]; };
  Exchange exchange(stats);
  std::vector<float> data;
  int q = pos < 2 * extra ? pos / 2 : pos - extra;
  bool active = true;
  if (pos < 2 * extra) {
    if (pos % 2 == 1) {
      exchange.send(image, covered, back_to_front[pos - 1]);
      active = false;
    } else {
      const ScreenBox b = exchange.receive(back_to_front[pos + 1], data);
      blend(image, b, data, /*nearer*/ true);
      covered = join(covered, b);
    }
  }
  int y0 = 0, y1 = image.height;
  if (active)
    for (int bit = 1; bit < P2; bit <<= 1) {
      const int partner = q ^ bit;
      const int mid = (y0 + y1) / 2;
      const bool farther = q < partner;  // the farther keeps the upper rows
      const int keep0 = farther ? y0 : mid, keep1 = farther ? mid : y1;
      const ScreenBox give = farther ? rows_of(covered, mid, y1) : rows_of(covered, y0, mid);
      const ScreenBox b = exchange.swap(image, give, rank_of(partner), data);
      blend(image, b, data, /*partner nearer*/ farther);
      covered = join(rows_of(covered, keep0, keep1), b);
      y0 = keep0, y1 = keep1;
    }
  // Rank 0 gathers each participant's band (its covered box within the band).
  if (comm.rank == 0) {
    Image whole(image.width, image.height);
    if (active)
      for (int j = std::max(covered.y0, y0); j < std::min(covered.y1, y1); ++j)
        std::copy(image.pixel(covered.x0, j), image.pixel(covered.x1, j), whole.pixel(covered.x0, j));
    for (int k = 0; k < P2; ++k) {
      if (rank_of(k) == 0) continue;
      const ScreenBox b = exchange.receive(rank_of(k), data);
      for (int j = b.y0; j < b.y1; ++j)
        std::copy(data.data() + static_cast<std::size_t>(j - b.y0) * b.width() * 4,
                  data.data() + static_cast<std::size_t>(j - b.y0 + 1) * b.width() * 4, whole.pixel(b.x0, j));
    }
    image = std::move(whole);
  } else if (active) {
    exchange.send(image, rows_of(covered, y0, y1), 0);
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return stats;
}

}  // namespace cellproj

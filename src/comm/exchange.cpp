#include "comm/exchange.hpp"

#include <mpi.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "comm/mpi_check.hpp"
#include "util/timer.hpp"

namespace crumple::comm {

namespace {
constexpr int kTag = 11;
}  // namespace

struct Exchange::Requests {
  std::vector<MPI_Request> handles;
};

Exchange::Exchange() = default;
Exchange::Exchange(Exchange&&) noexcept = default;
Exchange& Exchange::operator=(Exchange&&) noexcept = default;
Exchange::~Exchange() = default;

Exchange::Exchange(Communicator& comm, std::vector<Peer> peers, int components, int fields)
    : comm_(&comm),
      components_(static_cast<std::size_t>(components)),
      fields_(static_cast<std::size_t>(fields)),
      requests_(std::make_unique<Requests>()) {
  std::erase_if(peers, [](const Peer& p) { return p.send.empty() && p.recv.empty(); });
  const std::size_t width = components_ * fields_;
  send_offset_.assign(1, 0);
  recv_offset_.assign(1, 0);
  for (const Peer& p : peers) {
    if (p.rank < 0 || p.rank >= comm.size())
      throw std::invalid_argument("exchange: peer rank " + std::to_string(p.rank) +
                                  " outside the communicator");
    // A message to itself is a copy from the send buffer to the receive buffer.
    if (p.rank == comm.rank() && p.send.size() != p.recv.size())
      throw std::invalid_argument("exchange: a rank receives from itself what it sends itself");
    send_offset_.push_back(send_offset_.back() + width * p.send.size());
    recv_offset_.push_back(recv_offset_.back() + width * p.recv.size());
  }
  send_buffer_.resize(send_offset_.back());
  recv_buffer_.resize(recv_offset_.back());
  peers_ = std::move(peers);
  requests_->handles.reserve(2 * peers_.size());
}

void Exchange::checkFields(std::size_t given) const {
  if (given != fields_)
    throw std::logic_error("exchange: " + std::to_string(given) + " fields given, the plan has " +
                           std::to_string(fields_));
}

void Exchange::begin(std::initializer_list<std::span<const double>> from) {
  if (empty()) return;
  checkFields(from.size());
  if (in_flight_) throw std::logic_error("exchange: begin again before end");
  std::size_t k = 0;
  for (const Peer& p : peers_)
    for (const int32_t i : p.send)
      for (const auto& field : from)
        for (std::size_t c = 0; c < components_; ++c)
          send_buffer_[k++] = field[components_ * static_cast<std::size_t>(i) + c];
  post();
  in_flight_ = true;
}

void Exchange::post() {
  util::ScopedTimer timer(comm_->seconds_);
  auto& handles = requests_->handles;
  handles.clear();
  // Receives first, so that a message arriving early has its buffer.
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    const int peer = peers_[q].rank;
    const std::size_t n = recv_offset_[q + 1] - recv_offset_[q];
    if (peer == comm_->rank() || n == 0) continue;
    check(MPI_Irecv(recv_buffer_.data() + recv_offset_[q], static_cast<int>(n), MPI_DOUBLE, peer,
                    kTag, MPI_COMM_WORLD, &handles.emplace_back()),
          "Irecv");
  }
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    const int peer = peers_[q].rank;
    const auto first = send_buffer_.begin() + std::ptrdiff_t(send_offset_[q]);
    const auto last = send_buffer_.begin() + std::ptrdiff_t(send_offset_[q + 1]);
    if (peer == comm_->rank())
      std::copy(first, last, recv_buffer_.begin() + std::ptrdiff_t(recv_offset_[q]));
    if (peer == comm_->rank() || first == last) continue;
    check(MPI_Isend(&*first, static_cast<int>(last - first), MPI_DOUBLE, peer, kTag, MPI_COMM_WORLD,
                    &handles.emplace_back()),
          "Isend");
  }
}

void Exchange::end(std::initializer_list<std::span<double>> to) {
  if (empty()) return;
  checkFields(to.size());
  if (!in_flight_) throw std::logic_error("exchange: end without begin");
  in_flight_ = false;
  auto& handles = requests_->handles;
  if (!handles.empty()) {
    util::ScopedTimer timer(comm_->seconds_);
    check(MPI_Waitall(static_cast<int>(handles.size()), handles.data(), MPI_STATUSES_IGNORE),
          "Waitall");
  }
  std::size_t k = 0;
  for (const Peer& p : peers_)
    for (const int32_t i : p.recv)
      for (const auto& field : to)
        for (std::size_t c = 0; c < components_; ++c)
          field[components_ * static_cast<std::size_t>(i) + c] = recv_buffer_[k++];
}

}  // namespace crumple::comm

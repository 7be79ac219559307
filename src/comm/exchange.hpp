// A fixed pattern of point-to-point messages between neighbour ranks, after DOLFINx's
// Scatterer: the plan (which entries go to which peer, which entries each peer fills) is made
// once, and every use packs, sends, receives and unpacks along it. The exchange owns its
// buffers and its requests, so callers hand over arrays, not messages, and several exchanges
// may be in flight at once (begun in the same order on every rank: messages between two ranks
// match in the order they were posted).
//
// An entry is `components` doubles in each of `fields` arrays (positions and velocities of a
// node travel together: 2 fields of 3). Field f of entry i is field[f][components * i + c].
// Both sides list the entries of a message in the same order, so messages carry values only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <vector>

#include "comm/communicator.hpp"

namespace crumple::comm {

class Exchange {
 public:
  // What this rank sends to one peer and receives from it. Either list may be empty (contact
  // nodes travel one way); the peer's plan has the same lists the other way round.
  struct Peer {
    int rank = 0;
    std::vector<int32_t> send;  // entries packed for the peer, in the order it unpacks them
    std::vector<int32_t> recv;  // entries filled from the peer, in the order it packs them
  };

  Exchange();  // no peers: begin and end do nothing
  // Peers with nothing either way are dropped. A peer may be this rank itself (then the values
  // are copied, without MPI), with as many entries received as sent. Throws
  // std::invalid_argument for a peer rank outside the communicator.
  Exchange(Communicator& comm, std::vector<Peer> peers, int components, int fields = 1);
  Exchange(Exchange&&) noexcept;
  Exchange& operator=(Exchange&&) noexcept;
  ~Exchange();

  bool empty() const { return peers_.empty(); }
  // Packs the send entries of every field and posts every receive and send (non-blocking:
  // work may go on until end; `from` may change meanwhile, it has been copied).
  void begin(std::initializer_list<std::span<const double>> from);
  // Waits for every message and unpacks the received entries into the fields of `to`.
  void end(std::initializer_list<std::span<double>> to);

 private:
  struct Requests;  // MPI requests in flight (communicator.cpp's types stay in src/comm)
  void post();
  void checkFields(std::size_t given) const;

  Communicator* comm_ = nullptr;
  std::vector<Peer> peers_;
  std::size_t components_ = 0, fields_ = 0;
  // Per peer, where its messages start in the buffers (peers_.size() + 1 offsets, doubles).
  std::vector<std::size_t> send_offset_, recv_offset_;
  std::vector<double> send_buffer_, recv_buffer_;
  std::unique_ptr<Requests> requests_;
  bool in_flight_ = false;
};

}  // namespace crumple::comm

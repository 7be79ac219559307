// The model travels from rank 0 to the others as bytes: the round trip must give the same
// model, field for field, and the same subdomain (so the same results) on every rank.
#include <gtest/gtest.h>

#include "domain/subdomain.hpp"
#include "model/build.hpp"
#include "model/serialize.hpp"
#include "util/archive.hpp"

namespace {

using crumple::model::Model;

TEST(Serialize, ModelRoundTripKeepsEveryField) {
  const Model m = crumple::model::readModel(std::string(CRUMPLE_SOURCE_DIR) +
                                            "/tests/data/decks/mixed_conditions.k");
  const auto bytes = crumple::model::serialize(m);
  const Model r = crumple::model::deserialize(bytes);
  EXPECT_EQ(r.title, m.title);
  EXPECT_EQ(r.nodes.id, m.nodes.id);
  EXPECT_EQ(r.nodes.x, m.nodes.x);
  EXPECT_EQ(r.solids.id, m.solids.id);
  EXPECT_EQ(r.solids.part, m.solids.part);
  EXPECT_EQ(r.solids.nodes, m.solids.nodes);
  ASSERT_EQ(r.parts.size(), m.parts.size());
  for (std::size_t i = 0; i < m.parts.size(); ++i) {
    EXPECT_EQ(r.parts[i].id, m.parts[i].id);
    EXPECT_EQ(r.parts[i].title, m.parts[i].title);
    EXPECT_EQ(r.parts[i].hourglass, m.parts[i].hourglass);
    EXPECT_EQ(r.parts[i].where.str(), m.parts[i].where.str());
  }
  ASSERT_EQ(r.materials.size(), m.materials.size());
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    EXPECT_EQ(r.materials[i].law.index(), m.materials[i].law.index());
    EXPECT_EQ(r.materials[i].rho, m.materials[i].rho);
  }
  const auto& law = std::get<crumple::materials::PiecewiseLinear::Params>(r.materials[0].law);
  EXPECT_EQ(law.fail,
            std::get<crumple::materials::PiecewiseLinear::Params>(m.materials[0].law).fail);
  EXPECT_EQ(r.curves.size(), m.curves.size());
  EXPECT_EQ(r.curves[0].y, m.curves[0].y);
  EXPECT_EQ(r.node_sets, m.node_sets);
  EXPECT_EQ(r.segment_sets, m.segment_sets);
  EXPECT_EQ(r.prescribed.size(), m.prescribed.size());
  EXPECT_EQ(r.pressure_loads.size(), m.pressure_loads.size());
  EXPECT_EQ(r.initial_velocity, m.initial_velocity);
  EXPECT_EQ(r.history_nodes, m.history_nodes);
  ASSERT_EQ(r.rigid_walls.size(), 1u);
  EXPECT_EQ(r.rigid_walls[0].moving, m.rigid_walls[0].moving);
  EXPECT_EQ(r.rigid_walls[0].mass, m.rigid_walls[0].mass);
  EXPECT_EQ(r.controls.dt2ms, m.controls.dt2ms);
  EXPECT_EQ(r.controls.hourglass_ihq, m.controls.hourglass_ihq);
  // The index maps are rebuilt.
  EXPECT_EQ(r.nodeIndex(m.nodes.id.back()), m.nodeIndex(m.nodes.id.back()));
  EXPECT_EQ(r.partIndex(2), m.partIndex(2));
  // Serialising the copy gives the same bytes.
  EXPECT_EQ(crumple::model::serialize(r), bytes);
}

TEST(Serialize, TruncatedArchiveIsAnErrorNotACrash) {
  crumple::util::ArchiveWriter w;
  w.put(std::vector<double>{1.0, 2.0, 3.0});
  auto bytes = w.bytes();
  bytes.resize(bytes.size() - 4);
  crumple::util::ArchiveReader r(bytes);
  std::vector<double> v;
  EXPECT_THROW(r.get(v), std::runtime_error);
}

TEST(Serialize, EmptyVectorsRoundTrip) {
  crumple::util::ArchiveWriter w;
  w.put(std::vector<int64_t>{});
  w.put(std::string());
  crumple::util::ArchiveReader r(w.bytes());
  std::vector<int64_t> v{7};
  std::string s = "x";
  r.get(v);
  r.get(s);
  EXPECT_TRUE(v.empty());
  EXPECT_TRUE(s.empty());
  EXPECT_TRUE(r.atEnd());
}

}  // namespace

#include "model/serialize.hpp"

#include "util/archive.hpp"
#include "util/fields.hpp"

namespace crumple::model {

namespace {

using util::ArchiveReader;
using util::ArchiveWriter;

// Every field of every Model type, once for writing and once for reading; the two visit
// functions below must list the same fields in the same order. util::fieldCount at the top of
// each list makes a member added to a struct but not to its list a build error.
template <class A, class L>
void loc(A& a, L& l) {
  util::fieldCount<2>(l);
  a(l.file);
  a(l.line);
}

template <class A, class M>
void fields(A& a, M& m) {
  a(m.title);
  a(m.deck_path);
  util::fieldCount<2>(m.units);
  a(m.units.name);
  a(m.units.source);
  util::fieldCount<2>(m.nodes);
  // The element lists' base (solids, shells, beams and discretes add to it: no check there).
  util::fieldCount<3>(static_cast<const model::ElementList<8>&>(m.solids));
  a(m.nodes.id);
  a(m.nodes.x);
  a(m.solids.id);
  a(m.solids.part);
  a(m.solids.nodes);
  a(m.solids.mid);
  a(m.shells.id);
  a(m.shells.part);
  a(m.shells.nodes);
  a(m.shells.thickness);
  a(m.beams.id);
  a(m.beams.part);
  a(m.beams.nodes);
  a(m.beams.orientation);
  a(m.beams.section);
  a(m.discretes.id);
  a(m.discretes.part);
  a(m.discretes.nodes);
  a(m.discretes.scale);
  a(m.discretes.offset);
  a(m.sph.dim);
  a(m.sph.node);
  a(m.sph.part);
  a(m.sph.mass);
  a.count(
      m.parts.size(),
      [&](auto& p) {
        util::fieldCount<12>(p);
        a(p.id);
        a(p.title);
        a(p.section_kind);
        a(p.section);
        a(p.material);
        a(p.hourglass);
        a(p.eos);
        a(p.contact_ssf);
        a(p.contact_thickness);
        a(p.stiffness_damping);
        a(p.stiffness_fraction);
        loc(a, p.where);
      },
      m.parts);
  a.count(
      m.solid_sections.size(),
      [&](auto& s) {
        util::fieldCount<8>(s);
        a(s.id);
        a(s.elform);
        loc(a, s.where);
        a(s.nip);
        a(s.shrf);
        a(s.lobatto);
        a(s.zeta);
        a(s.weight);
      },
      m.solid_sections);
  a.count(
      m.shell_sections.size(),
      [&](auto& s) {
        util::fieldCount<10>(s);
        a(s.id);
        a(s.elform);
        a(s.shrf);
        a(s.nip);
        a(s.lobatto);
        a(s.t);
        a(s.zeta);
        a(s.weight);
        a(s.ply_angle);
        loc(a, s.where);
      },
      m.shell_sections);
  a.count(
      m.beam_sections.size(),
      [&](auto& s) {
        util::fieldCount<17>(s);
        a(s.id);
        a(s.elform);
        a(s.shrf);
        a(s.qr);
        a(s.integration);
        a(s.cst);
        a(s.ts1);
        a(s.ts2);
        a(s.tt1);
        a(s.tt2);
        a(s.a);
        a(s.iss);
        a(s.itt);
        a(s.j);
        a(s.sa);
        a(s.release);
        loc(a, s.where);
      },
      m.beam_sections);
  a.count(
      m.beam_integrations.size(),
      [&](auto& r) {
        util::fieldCount<5>(r);
        a(r.id);
        a(r.normalized);
        a(r.ra);
        a(r.points);
        loc(a, r.where);
      },
      m.beam_integrations);
  a.count(
      m.discrete_sections.size(),
      [&](auto& s) {
        util::fieldCount<3>(s);
        a(s.id);
        a(s.dro);
        loc(a, s.where);
      },
      m.discrete_sections);
  a.count(
      m.sph_sections.size(),
      [&](auto& s) {
        util::fieldCount<6>(s);
        a(s.id);
        a(s.cslh);
        a(s.hmin);
        a(s.hmax);
        a(s.sphini);
        loc(a, s.where);
      },
      m.sph_sections);
  a.count(
      m.materials.size(),
      [&](auto& mat) {
        util::fieldCount<6>(mat);
        a(mat.id);
        a(mat.title);
        a(mat.rho);
        a.variant(mat.law);
        loc(a, mat.where);
        a(mat.erosion);
      },
      m.materials);
  a.count(
      m.eos.size(),
      [&](auto& e) {
        util::fieldCount<4>(e);
        a(e.id);
        a(e.title);
        a(e.eos);
        loc(a, e.where);
      },
      m.eos);
  a(m.hourglass);
  a.count(
      m.curves.size(),
      [&](auto& c) {
        util::fieldCount<4>(c);
        a(c.id);
        a(c.x);
        a(c.y);
        a(c.sidr);
      },
      m.curves);
  a.count(
      m.tables.size(),
      [&](auto& t) {
        util::fieldCount<5>(t);
        a(t.id);
        a(t.values);
        a(t.curve_ids);
        a(t.curves);
        loc(a, t.where);
      },
      m.tables);
  a(m.node_sets);
  a(m.part_sets);
  a(m.segment_sets);
  for (auto& sets : m.element_sets) a(sets);
  a(m.tshell_sets);
  a(m.spcs);
  a(m.prescribed);
  a(m.nodal_loads);
  a(m.pressure_loads);
  a(m.blasts);
  a(m.airbags);
  a(m.body_loads);
  a.count(
      m.rigid_walls.size(),
      [&](auto& w) {
        util::fieldCount<17>(w);
        a(w.id);
        a(w.nodes);
        a(w.tail);
        a(w.normal);
        a(w.fric);
        a(w.finite);
        a(w.l_axis);
        a(w.lenl);
        a(w.lenm);
        a(w.moving);
        a(w.mass);
        a(w.v0);
        a(w.shape);
        a(w.lenp);
        a(w.radius);
        a(w.length);
        loc(a, w.where);
      },
      m.rigid_walls);
  a(m.initial_velocity);
  a(m.initial_angular_velocity);
  a(m.point_masses);
  a(m.history_nodes);
  for (auto& h : m.history_elements) a(h);
  a.count(
      m.cross_sections.size(),
      [&](auto& c) {
        util::fieldCount<13>(c);
        a(c.id);
        a(c.title);
        a(c.parts);
        a(c.center);
        a(c.normal);
        a(c.l);
        a(c.lenl);
        a(c.lenm);
        a(c.radius);
        a(c.by_set);
        a(c.set_nodes);
        for (auto& e : c.set_elements) a(e);
        loc(a, c.where);
      },
      m.cross_sections);
  a.count(
      m.beam_preloads.size(),
      [&](auto& p) {
        util::fieldCount<5>(p);
        a(p.beams);
        a(p.curve);
        a(p.scale);
        a(p.kbend);
        loc(a, p.where);
      },
      m.beam_preloads);
  a.count(
      m.mass_damping.size(),
      [&](auto& d) {
        util::fieldCount<7>(d);
        a(d.global);
        a(d.curve);
        a(d.value);
        a(d.scale);
        a(d.nodes);
        a(d.weight);
        loc(a, d.where);
      },
      m.mass_damping);
  a.count(
      m.rigid.bodies.size(),
      [&](auto& b) {
        util::fieldCount<14>(b);
        a(b.id);
        a(b.nodal);
        a(b.parts);
        a(b.nodes);
        a(b.fixed);
        a(b.inertia_given);
        a(b.mass);
        a(b.cm);
        a(b.tensor);
        a(b.velocity_given);
        a(b.v0);
        a(b.w0);
        a(b.motions);
        loc(a, b.where);
      },
      m.rigid.bodies);
  a.count(
      m.rigid.welds.size(),
      [&](auto& w) {
        util::fieldCount<9>(w);
        a(w.id);
        a(w.nodes);
        a(w.sn);
        a(w.ss);
        a(w.n);
        a(w.m);
        a(w.tfail);
        a(w.generalized);
        loc(a, w.where);
      },
      m.rigid.welds);
  a.count(
      m.rigid.node_sets.size(),
      [&](auto& t) {
        util::fieldCount<5>(t);
        a(t.id);
        a(t.nodes);
        a(t.dofs);
        a(t.tfail);
        loc(a, t.where);
      },
      m.rigid.node_sets);
  a.count(
      m.rigid.joints.size(),
      [&](auto& j) {
        util::fieldCount<6>(j);
        a(j.id);
        a(j.kind);
        a(j.pairs);
        a(j.rps);
        a(j.damp);
        loc(a, j.where);
      },
      m.rigid.joints);
  a.count(
      m.rigid.joint_stiffness.size(),
      [&](auto& j) {
        util::fieldCount<8>(j);
        a(j.id);
        a(j.body_a);
        a(j.body_b);
        a(j.frame_a);
        a(j.frame_b);
        a(j.stiffness);
        a(j.friction);
        loc(a, j.where);
      },
      m.rigid.joint_stiffness);
  a.count(
      m.rigid.loads.size(),
      [&](auto& l) {
        util::fieldCount<5>(l);
        a(l.body);
        a(l.dof);
        a(l.curve);
        a(l.sf);
        loc(a, l.where);
      },
      m.rigid.loads);
  auto surface = [&](auto& sf) {
    util::fieldCount<12>(sf);
    a(sf.nodes);
    a(sf.segments);
    a(sf.segment_element);
    a(sf.segment_thickness);
    a(sf.segment_stiffness);
    a(sf.segment_depth);
    a(sf.segment_neighbour);
    a(sf.node_half_thickness);
    a(sf.edges);
    a(sf.edge_radius);
    a(sf.edge_stiffness);
    a(sf.edge_part);
  };
  a.count(
      m.contacts.size(),
      [&](auto& c) {
        util::fieldCount<31>(c);
        a(c.id);
        a(c.title);
        a(c.keyword);
        a(c.kind);
        a(c.automatic);
        a(c.offset);
        a(c.tie_rotations);
        a(c.tiebreak);
        surface(c.a);
        surface(c.b);
        a(c.fs);
        a(c.fd);
        a(c.dc);
        a(c.vdc);
        a(c.birth);
        a(c.death);
        a(c.sfs);
        a(c.sfm);
        a(c.sst);
        a(c.mst);
        a(c.tie_distance);
        a(c.soft);
        a(c.sofscl);
        a(c.sbopt);
        a(c.depth);
        a(c.bsort);
        a(c.ignore);
        a(c.dtstif);
        a(c.skip_same_part_edges);
        a(c.eroding);
        loc(a, c.where);
      },
      m.contacts);
  a(m.contact_controls);
  a(m.controls);
  a.count(
      m.unsupported.size(),
      [&](auto& u) {
        util::fieldCount<6>(u);
        a(u.keyword);
        a(u.reason);
        a(u.count);
        loc(a, u.first);
        a(u.changes_answer);
        a(u.feature);
      },
      m.unsupported);
  a.count(
      m.ignored.size(),
      [&](auto& f) {
        util::fieldCount<4>(f);
        a(f.keyword);
        a(f.field);
        a(f.reason);
        loc(a, f.where);
      },
      m.ignored);
}

struct Writer {
  ArchiveWriter w;
  template <class T>
  void operator()(const T& v) {
    w.put(v);
  }
  template <class F, class V>
  void count(std::size_t n, F&& each, const V& items) {
    w.put<uint64_t>(n);
    for (const auto& x : items) each(const_cast<typename V::value_type&>(x));
  }
  void variant(const MaterialLaw& law) {
    w.put<uint64_t>(law.index());
    std::visit([&](const auto& l) { w.put(l); }, law);
  }
};

struct Reader {
  ArchiveReader r;
  template <class T>
  void operator()(T& v) {
    r.get(v);
  }
  template <class F, class V>
  void count(std::size_t, F&& each, V& items) {
    uint64_t n = 0;
    r.get(n);
    items.resize(n);
    for (auto& x : items) each(x);
  }
  template <std::size_t I = 0>
  static void emplace(MaterialLaw& law, uint64_t index) {
    if constexpr (I < std::variant_size_v<MaterialLaw>) {
      if (index == I) {
        law.emplace<I>();
        return;
      }
      emplace<I + 1>(law, index);
    } else {
      throw std::runtime_error("archive: unknown material law");
    }
  }
  void variant(MaterialLaw& law) {
    uint64_t index = 0;
    r.get(index);
    emplace(law, index);
    std::visit([&](auto& l) { r.get(l); }, law);
  }
};

}  // namespace

std::vector<char> serialize(const Model& model) {
  Writer w;
  fields(w, const_cast<Model&>(model));
  return std::move(w.w.bytes());
}

Model deserialize(const std::vector<char>& bytes) {
  Model m;
  Reader r{ArchiveReader(bytes)};
  fields(r, m);
  m.finalize();
  return m;
}

}  // namespace crumple::model

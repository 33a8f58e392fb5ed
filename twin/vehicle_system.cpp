#include "twin/vehicle_system.hpp"

#include <utility>
#include <vector>

#include "common/errors.hpp"

namespace dtwin::sim {

namespace {

std::size_t contiguous(const std::vector<int>& slots) {
  DTWIN_CHECK(!slots.empty(), "empty slot list");
  for (std::size_t i = 1; i < slots.size(); ++i)
    DTWIN_CHECK(slots[i] == slots[0] + static_cast<int>(i), "slots not contiguous");
  return static_cast<std::size_t>(slots[0]);
}

}  // namespace

VehicleSystem::VehicleSystem(const Model& m, bool filter_states, bool link_hubs) : model(m) {
  build(filter_states, link_hubs);
}

double VehicleSystem::prescribedHubForce(const State& s, int c, double hub_zdd) const {
  // The wheel's balance along the strut axis z (it slides along it): the road's vertical L, its
  // weight and inertia, the fore-aft H = traction - m_w a (HubReactionElement) and the strut's F:
  // L = m_w (z'' + g) + (F - H z_x) / z_z.
  const VehicleData& d = model.vehicle();
  const double a = ctx.speed.accel(s.getTime());
  const double H = (ctx.traction_per_wheel_per_accel - d.wheel_mass) * a;
  const Vec3 z(struts[c].upper.getBodyRotation(s).z());
  return d.wheel_mass * (hub_zdd + d.gravity) + (strut_force_[c](s) - H * z[0]) / z[2];
}

void VehicleSystem::installAxleCouplings() {
  const Model& M = model;
  for (std::size_t i = 0; i < M.effects().size(); ++i)
    if (M.effects()[i]->kind() == EffectKind::AxleCoupling)
      for (int ax = 0; ax < 2; ++ax) {
        auto* ce = new AxleCouplingElement(&ctx, M.effects()[i].get(),
                                           static_cast<std::size_t>(M.effectSlots()[i][0]),
                                           &struts[2 * ax], &struts[2 * ax + 1], ax == 0);
        Force::Custom(forces, ce);
        if (!prescribed_hubs) continue;
        for (int side = 0; side < 2;
             ++side) {  // the coupling pushes the left strut by F, the right by -F
          auto& f = strut_force_[2 * ax + side];
          f = [f, ce, sign = side == 0 ? 1.0 : -1.0](const State& s) {
            return f(s) + sign * ce->pairForce(s);
          };
        }
      }
}

void VehicleSystem::build(bool filter_states, bool link_hubs) {
  const Model& M = model;
  const VehicleData& d = M.vehicle();
  prescribed_hubs =
      M.tire().followsSignal() && M.topology() == SuspensionTopology::MacPherson && !link_hubs;
  std::vector<StrutElement*> slider_elems;
  const Rotation xToZ(-Pi / 2, YAxis);  // a slider's x axis along the parent's z
  const Rotation zToX(Pi / 2, YAxis);   // a pin's z axis along the parent's x
  const double z_wc =
      -(d.cg_height - M.table().value("tire.unloaded_radius_m"));  // wheel centre below CG
  // A wheel carrier slides along the chassis z: the chassis's roll and pitch carry it sideways and
  // fore-aft, m_w z_wc² each. With the hubs' motion prescribed there is no wheel body to carry it,
  // so the chassis does (the same kinetic energy; the vertical motion stays the signal's).
  const double carried = prescribed_hubs ? 4.0 * d.wheel_mass * z_wc * z_wc : 0.0;
  heave =
      MobilizedBody::Slider(matter.Ground(), Transform(xToZ), Body::Massless(), Transform(xToZ));
  chassis = MobilizedBody::Universal(
      heave, Transform(),
      Body::Rigid(MassProperties(d.chassis_mass, Vec3(0),
                                 Inertia(d.ixx + carried, d.iyy + carried, d.izz))),
      Transform());
  const Body::Rigid wheelBody(MassProperties(d.wheel_mass, Vec3(0), Inertia(1e-3)));
  std::vector<std::pair<MobilizedBody, double>> massive = {{chassis, d.chassis_mass}};
  for (int c = 0; c < 4; ++c) {
    const double x = isFront(c) ? d.a : -d.b;
    const double y = (cornerTrack(c) == Track::Left ? 0.5 : -0.5) * d.track;
    strut_preload[c] = M.staticStrutForce(c);
    if (prescribed_hubs) {
      struts[c].upper = chassis;
      struts[c].st_upper = Vec3(x, y, z_wc);
      struts[c].is_prescribed = true;
      struts[c].ctx = &ctx;
      struts[c].tire = &tires[static_cast<std::size_t>(c)];
    } else if (M.topology() == SuspensionTopology::MacPherson) {
      wheels[c] = MobilizedBody::Slider(chassis, Transform(xToZ, Vec3(x, y, z_wc)), wheelBody,
                                        Transform(xToZ));
      struts[c] = {chassis, wheels[c], Vec3(x, y, z_wc), Vec3(0)};
    }
  }
  if (M.topology() == SuspensionTopology::SolidAxle) {
    const Body::Rigid axleBody(
        MassProperties(d.axle_mass, Vec3(0), Inertia(d.axle_ixx, d.axle_ixx, d.axle_ixx)));
    for (int ax = 0; ax < 2; ++ax) {
      const double x = ax == 0 ? d.a : -d.b;
      axle_slider[ax] = MobilizedBody::Slider(chassis, Transform(xToZ, Vec3(x, 0, z_wc)),
                                              Body::Massless(), Transform(xToZ));
      axle[ax] = MobilizedBody::Pin(axle_slider[ax], Transform(zToX), axleBody, Transform(zToX));
      massive.push_back({axle[ax], d.axle_mass});
      for (int side = 0; side < 2; ++side) {
        const int c = 2 * ax + side;
        const double sgn = side == 0 ? 1.0 : -1.0;
        wheels[c] = MobilizedBody::Slider(
            axle[ax], Transform(xToZ, Vec3(0, sgn * 0.5 * d.track, 0)), wheelBody, Transform(xToZ));
        struts[c] = {chassis, axle[ax], Vec3(x, sgn * 0.5 * d.spring_track, z_wc),
                     Vec3(0, sgn * 0.5 * d.spring_track, 0)};
        // Wheel/axle compliant interface (paper eq. 5): no effects, preload from the data.
        StrutGeometry iface{axle[ax], wheels[c], Vec3(0, sgn * 0.5 * d.track, 0), Vec3(0)};
        auto* ie =
            new StrutElement(&ctx, &M, &M.interfaceLaw(), iface, contiguous(M.interfaceSlots()),
                             M.interfacePreloadSlot(), 0.0, false);
        ie->bind_slider_ = true;  // the wheel slides on the axle along the axle's z
        slider_elems.push_back(ie);
        Force::Custom(forces, ie);
      }
    }
  }
  for (int c = 0; c < 4; ++c) {
    if (!prescribed_hubs) massive.push_back({wheels[c], d.wheel_mass});
    auto* se =
        new StrutElement(&ctx, &M, &M.strut(), struts[c], contiguous(M.suspensionSlots()), -1,
                         strut_preload[c], true, filter_states, forces.getMySubsystemIndex());
    se->placeAt(c);
    se->factors_ = M.strutFactors()[static_cast<std::size_t>(c)];
    if (prescribed_hubs) {
      strut_force_[c] = [se](const State& s) { return se->totalForce(s); };
    } else if (M.topology() == SuspensionTopology::MacPherson) {
      se->bind_slider_ = true;  // the wheel carrier slides along the chassis z at the strut
    } else {
      const int ax = c / 2;
      se->seat_slider_ = axle_slider[ax];
      se->seat_pin_ = axle[ax];
      se->seat_y_ = struts[c].st_lower[1];
    }
    se->partner_ = &struts[c ^ 1];  // corners 2 ax + side: the other side of the axle
    se->front_ = isFront(c);
    se->tire_ = &tires[static_cast<std::size_t>(c)];
    se->wheel_ = wheels[c];
    slider_elems.push_back(se);
    Force::Custom(forces, se);
    TireCorner tc;
    tc.model = &M;
    tc.corner = c;
    tc.p0 = contiguous(M.tireSlots());
    tc.np = M.tireSlots().size();
    tc.r0 = parameterIndex(M.tire().parameters(), "unloaded_radius_m");
    tc.factors = M.tireFactors()[static_cast<std::size_t>(c)];
    for (std::size_t i = 0; i < M.effects().size(); ++i)
      if (!M.effectActsAt(i, c))
        continue;  // installed at another corner
      else if (M.effects()[i]->kind() == EffectKind::TireInput)
        tc.filters.push_back(
            {M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
      else if (M.effects()[i]->kind() == EffectKind::TireForce)
        tc.scalers.push_back(
            {M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
      else if (M.effects()[i]->kind() == EffectKind::TireLoad)
        tc.loads.push_back({M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
    tires[c] = tc;
    if (prescribed_hubs)
      Force::Custom(forces, new HubReactionElement(&ctx, &struts[c], d.wheel_mass));
    else
      Force::Custom(forces, new TireElement(&ctx, tc, wheels[c]));
  }
  installAxleCouplings();
  for (std::size_t i = 0; i < M.effects().size(); ++i)
    if (M.effects()[i]->kind() == EffectKind::ChassisForce)
      Force::Custom(forces, new ChassisForceElement(&ctx, M.effects()[i].get(),
                                                    static_cast<std::size_t>(M.effectSlots()[i][0]),
                                                    heave, chassis));
  Force::Custom(forces, new BodyLoadElement(&ctx, massive, d.gravity));
  ctx.traction_per_wheel_per_accel = d.total_mass(M.topology()) / 4.0;
  system.realizeTopology();
  default_state = system.getDefaultState();
  for (auto* e : slider_elems) e->bind(default_state);
  heave_q = heave.getFirstQIndex(default_state);
  heave_u = heave.getFirstUIndex(default_state);
  chassis_q = chassis.getFirstQIndex(default_state);
  chassis_u = chassis.getFirstUIndex(default_state);
  for (int c = 0; c < 4; ++c) {
    if (prescribed_hubs) continue;
    if (M.topology() == SuspensionTopology::MacPherson)
      struts[c].bindSlider(default_state);
    else
      struts[c].bindAxleSeat(default_state, axle_slider[c / 2], axle[c / 2], struts[c].st_lower[1]);
  }
}

}  // namespace dtwin::sim

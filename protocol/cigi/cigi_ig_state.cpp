// The IG's state from a host's packets (cigi_ig_state.h).
#include "protocol/cigi/cigi_ig_state.h"

#include <type_traits>

#include "geodesy/utc_time.h"

namespace cloudsvc::cigi {

IgState::IgState(ViewFrustum default_frustum) : default_frustum_(default_frustum) {}

std::vector<std::string> IgState::apply(const HostDatagram& d) {
  std::vector<std::string> refused;
  if (!d.usable) return refused;
  ++datagrams_;
  mode_ = d.ig_control.mode;
  last_host_frame_ = d.ig_control.host_frame;
  host_timestamp_s_.reset();
  if (d.ig_control.timestamp_valid) host_timestamp_s_ = d.ig_control.timestamp / kTimestampTicksPerSecond;
  for (const HostPacket& p : d.packets)
    if (std::optional<std::string> problem = apply(p)) refused.push_back(*problem);
  return refused;
}

std::vector<View> IgState::views() const {
  if (views_.empty()) return {View{0, 0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, default_frustum_}};
  std::vector<View> out;
  for (const auto& [id, v] : views_) out.push_back(v);
  return out;
}

std::optional<std::string> IgState::apply(const HostPacket& packet) {
  return std::visit(
      [this](const auto& p) -> std::optional<std::string> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, EntityControl>) {
          // The reader keeps entity 0 only; its state (active, destroyed) does not remove the eye.
          ownship_ = OwnshipPose{p.lat_deg, p.lon_deg, p.alt_m, p.roll_deg, p.pitch_deg, p.yaw_deg};
        } else if constexpr (std::is_same_v<P, ViewControl> || std::is_same_v<P, ViewDefinition>) {
          // The view as the packet leaves it, checked before anything changes.
          const auto known = views_.find(p.view_id);
          if (known == views_.end() && views_.size() >= kMaxViews)
            return packet_name(std::is_same_v<P, ViewControl> ? opcode::kViewControl : opcode::kViewDefinition) +
                   " of view " + std::to_string(p.view_id) + ": the IG draws at most " + std::to_string(kMaxViews) +
                   " views";
          View v = known != views_.end() ? known->second : View{p.view_id, 0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, default_frustum_};
          v.group = p.group_id;
          if constexpr (std::is_same_v<P, ViewControl>) {
            using namespace view_enable;
            if (p.enable & kX) v.x_m = p.x_m;
            if (p.enable & kY) v.y_m = p.y_m;
            if (p.enable & kZ) v.z_m = p.z_m;
            if (p.enable & kRoll) v.roll_deg = p.roll_deg;
            if (p.enable & kPitch) v.pitch_deg = p.pitch_deg;
            if (p.enable & kYaw) v.yaw_deg = p.yaw_deg;
          } else {
            using namespace definition_enable;
            ViewFrustum& f = v.frustum;
            if (p.enable & kNear) f.near_m = p.near_m;
            if (p.enable & kFar) f.far_m = p.far_m;
            if (p.enable & kLeft) f.left_deg = p.left_deg;
            if (p.enable & kRight) f.right_deg = p.right_deg;
            if (p.enable & kTop) f.top_deg = p.top_deg;
            if (p.enable & kBottom) f.bottom_deg = p.bottom_deg;
            v.mirror = p.mirror;  // not under an enable bit
            // The packet's own fields passed their checks; together with the view's others
            // they must still make a frustum.
            if (!(f.right_deg > f.left_deg && f.top_deg > f.bottom_deg && (f.far_m <= 0.0f || f.far_m > f.near_m)))
              return "View Definition of view " + std::to_string(p.view_id) +
                     ": with the view's other fields no frustum (left < right, bottom < top, near < far)";
          }
          views_[p.view_id] = v;
        } else if constexpr (std::is_same_v<P, CelestialSphereControl>) {
          if (p.date_valid)
            utc_s_ = geo::utc_from_civil(static_cast<int>(p.date % 10000), static_cast<int>(p.date / 1000000),
                                         static_cast<int>(p.date / 10000 % 100), p.hour, p.minute, 0);
        } else if constexpr (std::is_same_v<P, AtmosphereControl>) {
          // The reader refused it whole if a field was not finite: the visibility is a number.
          if (!atmosphere_ || atmosphere_->visibility_m != p.visibility_m) ++atmosphere_generation_;
          atmosphere_ = p;
        } else if constexpr (std::is_same_v<P, EnvironmentalRegionControl>) {
          if (p.state == 2) {  // destroyed
            if (regions_.erase(p.region_id) > 0) ++weather_generation_;
            return std::nullopt;
          }
          auto it = regions_.find(p.region_id);
          if (it == regions_.end()) {
            if (regions_.size() >= kMaxRegions)
              return "Environmental Region Control of region " + std::to_string(p.region_id) + ": the IG keeps at most " +
                     std::to_string(kMaxRegions) + " regions";
            it = regions_.emplace(p.region_id, Region{}).first;
          }
          // hosts resend their weather every frame: only a change makes the weather again
          if (!(it->second.control == p)) ++weather_generation_;
          it->second.control = p;
        } else if constexpr (std::is_same_v<P, WeatherControl>) {
          if (p.layer_id < kFirstCloudLayerId || p.layer_id > kLastCloudLayerId) return std::nullopt;  // fog, precipitation: not drawn
          CloudLayerSet* set = nullptr;
          if (p.scope == WeatherScope::Global) {
            set = &global_layers_;
          } else if (p.scope == WeatherScope::Regional) {
            auto it = regions_.find(p.entity_or_region_id);
            if (it == regions_.end())
              return "Weather Control of layer " + std::to_string(p.layer_id) + " in region " +
                     std::to_string(p.entity_or_region_id) + ": no such region (send its Environmental Region Control first)";
            set = &it->second.layers;
          } else {
            return std::nullopt;  // weather around an entity: not drawn
          }
          auto& slot = (*set)[p.layer_id - kFirstCloudLayerId];
          std::optional<WeatherControl> next;
          if (p.enabled && p.cloud_type != 0) next = p;
          // Hosts resend their weather every frame: only a change makes the weather again, and
          // the first Weather Control, which puts the weather in the host's hands even when it
          // only disables a layer.
          if (slot != next || weather_generation_ == 0) ++weather_generation_;
          slot = next;
        }
        return std::nullopt;
      },
      packet);
}

}  // namespace cloudsvc::cigi

//! The GPU objects [`super::setup`] needs beyond the tutorial's: comparison
//! samplers for each filter and fit.

use std::collections::BTreeMap;

/// Comparison samplers keyed by (linear filtering, clamp to border). The
/// border variants (border depth 1.0: lookups outside the map are lit) exist
/// when the device has `ADDRESS_MODE_CLAMP_TO_BORDER`.
pub fn comparison_samplers(device: &wgpu::Device) -> BTreeMap<(bool, bool), wgpu::Sampler> {
    let border_ok = device.features().contains(wgpu::Features::ADDRESS_MODE_CLAMP_TO_BORDER);
    let mut map = BTreeMap::new();
    for linear in [false, true] {
        for border in [false, true] {
            if border && !border_ok {
                continue;
            }
            let filter = if linear { wgpu::FilterMode::Linear } else { wgpu::FilterMode::Nearest };
            let address = if border { wgpu::AddressMode::ClampToBorder } else { wgpu::AddressMode::ClampToEdge };
            let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
                label: Some("shadow compare"),
                address_mode_u: address,
                address_mode_v: address,
                address_mode_w: address,
                mag_filter: filter,
                min_filter: filter,
                compare: Some(wgpu::CompareFunction::LessEqual),
                border_color: border.then_some(wgpu::SamplerBorderColor::OpaqueWhite),
                ..Default::default()
            });
            map.insert((linear, border), sampler);
        }
    }
    map
}

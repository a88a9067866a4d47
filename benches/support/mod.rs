//! Shared by the benchmarks: the programs they compile and a small timing
//! harness (warm-up, many samples, median and spread).

#![allow(dead_code)]

use std::time::Duration;

/// The project's scene program.
pub const SHADOW_DAS: &str = include_str!("../../shaders/shadow.das");
/// The WGSL program equivalent to `SHADOW_DAS`: same entry points, same
/// inputs, outputs and resources (see docs/performance.md).
pub const SHADOW_WGSL: &str = include_str!("../shadow_equivalent.wgsl");

/// One helper block of the scaled program: copies of the scene's helper
/// functions and of the lit fragment program's body as a function, all
/// suffixed with `k`. About as much source as the whole scene program.
fn block(k: usize) -> String {
    format!(
        r#"
// ---- generated block {k} ----
def sun_visibility_{k}(uv : float2; depth : float) : float {{
    let step = 1.0 / SHADOW_MAP_SIZE
    var lit = 0.0
    var taps = 0.0
    for (y in range(-PCF_RADIUS, PCF_RADIUS + 1)) {{
        for (x in range(-PCF_RADIUS, PCF_RADIUS + 1)) {{
            lit += textureCompare(shadow_map, uv + float2(x, y) * step, depth)
            taps += 1.0
        }}
    }}
    return lit / taps
}}

def floor_albedo_{k}(p : float3) : float3 {{
    let cell = floor(p.x * 0.5 + 100.0) + floor(p.z * 0.5 + 100.0)
    let odd = cell - 2.0 * floor(cell * 0.5)
    let shade = odd < 0.5 ? 0.85 : 0.30
    return float3(shade) * float3(0.80, 0.82, 0.88)
}}

def shade_{k}(world_pos : float3; world_normal : float3; light_space : float4) : float3 {{
    let n = normalize(world_normal)
    let l = normalize(u_light_dir)
    let v = normalize(u_cam_pos - world_pos)
    let ndotl = max(dot(n, l), 0.0)
    let clip_w = max(light_space.w, 0.0001)
    let ndc = light_space.xyz / clip_w
    let uv = ndc.xy * 0.5 + 0.5
    let depth = ndc.z * 0.5 + 0.5
    let bias = max(0.0025 * (1.0 - ndotl), 0.0008)
    var lit = sun_visibility_{k}(uv, depth - bias)
    if (ndotl < 0.05) {{
        lit = 0.0
    }}
    let up = n.y * 0.5 + 0.5
    let ambient = lerp(float3(0.10, 0.09, 0.08), float3(0.30, 0.34, 0.42), up)
    let sun_color = float3(1.30, 1.15, 0.90)
    var albedo = float3(0.85, 0.45, 0.30)
    var gloss = 0.5
    if (u_is_floor > 0.5) {{
        albedo = floor_albedo_{k}(world_pos)
        gloss = 0.15
    }}
    let h = normalize(l + v)
    let spec = pow(max(dot(n, h), 0.0), 48.0) * lit * gloss
    return albedo * (ambient + sun_color * (ndotl * lit)) + float3(spec)
}}
"#
    )
}

/// The scene program grown `factor` times: `factor - 1` generated helper
/// blocks, all reached from `main_fs` (the front end only compiles what the
/// entry points reach). `factor` 1 is the scene program unchanged.
pub fn scaled_source(factor: usize) -> String {
    if factor <= 1 {
        return SHADOW_DAS.to_string();
    }
    let last = "    f_FragColor = float4(color, 1.0)\n}";
    assert!(SHADOW_DAS.trim_end().ends_with(last.trim_end()), "shaders/shadow.das's last lines changed");
    let mut s = SHADOW_DAS.trim_end().strip_suffix(last.trim_end()).unwrap().to_string();
    s.push_str("    f_FragColor = float4(color + extras(v_world_pos, v_world_normal, v_light_space) * 0.001, 1.0)\n}\n");
    let mut calls = String::new();
    for k in 1..factor {
        s.push_str(&block(k));
        calls.push_str(&format!("    acc += shade_{k}(world_pos, world_normal, light_space)\n"));
    }
    s.push_str(&format!(
        "\ndef extras(world_pos : float3; world_normal : float3; light_space : float4) : float3 {{\n    var acc = float3(0.0)\n{calls}    return acc\n}}\n"
    ));
    s
}

/// CPU time of the whole process (CLOCK_PROCESS_CPUTIME_ID), every thread
/// summed: what the work costs, including umbrac's compiler and job threads,
/// without the time the scheduler gave the cores to other processes.
pub fn cpu_time() -> Duration {
    CpuTime::PROCESS.now()
}

/// A criterion measurement of CPU time by one clock: the whole process's
/// ([`CpuTime::PROCESS`]) or one thread's (`pthread_getcpuclockid`).
pub struct CpuTime(pub libc::clockid_t);

impl CpuTime {
    pub const PROCESS: CpuTime = CpuTime(libc::CLOCK_PROCESS_CPUTIME_ID);

    pub fn now(&self) -> Duration {
        let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
        // SAFETY: a valid pointer to a timespec; the clock is the process's
        // or a live thread's.
        unsafe { libc::clock_gettime(self.0, &mut ts) };
        Duration::new(ts.tv_sec as u64, ts.tv_nsec as u32)
    }
}

static WALL: criterion::measurement::WallTime = criterion::measurement::WallTime;

impl criterion::measurement::Measurement for CpuTime {
    type Intermediate = Duration;
    type Value = Duration;
    fn start(&self) -> Duration {
        self.now()
    }
    fn end(&self, i: Duration) -> Duration {
        self.now().saturating_sub(i)
    }
    fn add(&self, a: &Duration, b: &Duration) -> Duration {
        *a + *b
    }
    fn zero(&self) -> Duration {
        Duration::ZERO
    }
    fn to_f64(&self, v: &Duration) -> f64 {
        v.as_nanos() as f64
    }
    fn formatter(&self) -> &dyn criterion::measurement::ValueFormatter {
        criterion::measurement::Measurement::formatter(&WALL)
    }
}

/// Timing of repeated runs of one thing.
#[derive(Clone, Debug)]
pub struct Timing {
    pub samples: Vec<Duration>,
}

impl Timing {
    fn sorted(&self) -> Vec<f64> {
        let mut v: Vec<f64> = self.samples.iter().map(|d| d.as_secs_f64()).collect();
        v.sort_by(|a, b| a.partial_cmp(b).unwrap());
        v
    }
    fn quantile(&self, q: f64) -> f64 {
        let v = self.sorted();
        let i = ((v.len() - 1) as f64 * q).round() as usize;
        v[i]
    }
    /// Median, seconds.
    pub fn median(&self) -> f64 {
        self.quantile(0.5)
    }
    /// 10th and 90th percentiles, seconds.
    pub fn p10(&self) -> f64 {
        self.quantile(0.1)
    }
    pub fn p90(&self) -> f64 {
        self.quantile(0.9)
    }
}

/// Runs `f` `warmup` times, then `samples` timed times (each sample
/// `inner` calls, averaged); process CPU time.
pub fn time<T>(warmup: usize, samples: usize, inner: usize, mut f: impl FnMut() -> T) -> Timing {
    for _ in 0..warmup {
        std::hint::black_box(f());
    }
    let samples = (0..samples)
        .map(|_| {
            let t = cpu_time();
            for _ in 0..inner {
                std::hint::black_box(f());
            }
            cpu_time().saturating_sub(t) / inner.max(1) as u32
        })
        .collect();
    Timing { samples }
}

/// The checked program of `text` (preprocess, parse, check).
fn umbrac_check(text: &str) -> umbrac::sema::Program {
    let mut sources = umbrac::SourceMap::new();
    let root = sources.add("shadow.das", None, text.to_string(), None);
    let mut diags = umbrac::Diagnostics::new();
    let program = umbrac::syntax::parse(&mut sources, root, &Default::default(), &mut diags);
    let checked = umbrac::sema::check(&program, &mut diags).expect("checks");
    assert!(!diags.has_errors());
    checked
}

/// umbrac's front end: source text to one validated naga module, the
/// whole program's (WGSL/SPIR-V) module: the counterpart of naga's WGSL
/// front end, which makes one module.
pub fn umbrac_front_end(text: &str) -> (naga::Module, naga::valid::ModuleInfo) {
    let (module, info, _) = umbrac::lower::lower_gpu(&umbrac_check(text), umbrac::Conventions::Portable).expect("lowers");
    (module, info)
}

/// Source text to every module the emitters need: the GPU module and one GL
/// module per entry point, all validated.
pub fn umbrac_all_modules(text: &str) -> umbrac::Lowered {
    umbrac::lower::lower(&umbrac_check(text), umbrac::Conventions::Portable).expect("lowers")
}

/// naga's WGSL front end: parse and validate.
pub fn naga_front_end(text: &str) -> (naga::Module, naga::valid::ModuleInfo) {
    let module = naga::front::wgsl::parse_str(text).expect("parses");
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default())
        .validate(&module)
        .expect("validates");
    (module, info)
}

/// The whole compiler: every target and the reflection.
pub fn umbrac_all_targets(text: &str) -> umbrac::Compilation {
    let c = umbrac::compile_source("shadow.das", text, &umbrac::Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    c
}

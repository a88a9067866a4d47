//! A GL host can swap either stage of any program of daslang's twelve GL
//! tutorials between umbrac's GLSL and daslang's own generator's
//! (`../shared/reference/dasglsl-glsl/`): umbrac's vertex shader links
//! with dasGlsl's fragment shader and dasGlsl's vertex shader with
//! umbrac's fragment shader, in GLSL 330 (OpenGL 3.3) and ES 3.00
//! (OpenGL ES 3.0), and each mix draws what umbrac's own pair draws.
//!
//! Every pair is drawn once by the GL executor's probe
//! (`umbrac::render::exec::gl::probe`): 64x64, inputs made up from the
//! declared names and types (a grid mesh, fixed uniform values, pattern
//! textures), colour output 0 read back. What a small harness cannot give
//! is left out: transform feedback (07_particles' `sim_src` is drawn as a
//! plain draw, its fragment stage a dummy), instancing (one instance,
//! per-instance attributes fed per vertex), the other colour outputs of
//! the G-buffer programs (only output 0 is compared) and textures
//! rendered by earlier passes (a fixed pattern stands in).

use std::path::{Path, PathBuf};

use umbrac::render::consumer::Consumer;
use umbrac::render::exec::gl::probe::ProbeImage;

use crate::support;

const SIZE: u32 = 64;

/// Largest channel difference allowed at one pixel, and how many pixels
/// (of 4096) may exceed it. Swapping the vertex stage changes no pixel;
/// daslang's fragment stages differ from umbrac's by 1/255 on some pixels
/// in ES (they leave `sampler2D` at the default `lowp`) and on one pixel
/// by more (10_deferred's lighting, ES: literals printed with six
/// significant digits).
const CHANNEL_TOLERANCE: u8 = 3;
const PIXELS_OVER: usize = 41; // 1%

/// Programs whose picture is one colour with any inputs: 07_particles'
/// transform-feedback step (the host discards rasterisation) and the
/// depth-only shadow passes, whose fragment stages write a constant. Their
/// pictures still compare where the vertex stage puts the triangles.
const CONSTANT: &[(&str, &str)] = &[("07_particles", "sim_dummy_src"), ("08_shadow", "shadow_fs"), ("10_deferred", "shadow_fs"), ("12_gltf", "shadow_fs")];

/// Fragment programs where daslang's generator's own picture differs from
/// umbrac's, with the same vertex stage: it prints the hash constant
/// `43758.5453` as `43758.5`. A mix with its fragment stage is compared
/// with its own pair instead (only the vertex stage was swapped), and
/// that its pair differs from umbrac's is checked, so the list stays true.
const PEER_ROUNDS: &[(&str, &str)] = &[("10_deferred", "ssao_fs"), ("12_gltf", "ssao_fs")];

fn reference() -> Option<(PathBuf, PathBuf)> {
    let shared = support::repo().join("../shared/reference");
    let (tutorials, peer) = (shared.join("daslang-tutorials"), shared.join("dasglsl-glsl"));
    if !tutorials.is_dir() || !peer.is_dir() {
        support::skip(format!("{} or {} is not here", tutorials.display(), peer.display()));
        return None;
    }
    Some((tutorials, peer))
}

/// (tutorial, vertex entry, fragment entry, umbrac's vertex and fragment
/// GLSL, daslang's) for every program, per profile: GLSL 330, ES 3.00.
type Pair = (String, String, String, [String; 2], [String; 2]);

fn pairs(tutorials: &Path, peer: &Path) -> [Vec<Pair>; 2] {
    let mut files: Vec<PathBuf> = std::fs::read_dir(tutorials).unwrap().map(|e| e.unwrap().path()).filter(|p| p.extension().is_some_and(|x| x == "das")).collect();
    files.sort();
    assert_eq!(files.len(), 12, "daslang's twelve GL tutorials");
    let mut out = [Vec::new(), Vec::new()];
    let options = umbrac::Options { targets: vec![umbrac::Target::Glsl330, umbrac::Target::Gles300], ..Default::default() };
    for f in &files {
        let stem = f.file_stem().unwrap().to_string_lossy().into_owned();
        let c = umbrac::compile_file(f, &options);
        let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{stem} compiles:\n{}", c.render_diagnostics()));
        let r = &compiled.reflection;
        for (profile, (target, sub)) in [("glsl330", ""), ("gles300", "es300/")].into_iter().enumerate() {
            let ours = |entry: &str| {
                let ep = r.entry_points.iter().find(|e| e.name == entry).expect("a program's entry point");
                compiled.artifact(&ep.files[target]).expect("every GLSL file is emitted").text().into_owned()
            };
            let theirs = |entry: &str| {
                let path = peer.join(&stem).join(format!("{sub}{entry}.glsl"));
                std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
            };
            for p in &r.programs {
                out[profile].push((stem.clone(), p.vertex.clone(), p.fragment.clone(), [ours(&p.vertex), ours(&p.fragment)], [theirs(&p.vertex), theirs(&p.fragment)]));
            }
        }
    }
    out
}

/// Pixels whose largest channel difference is over the tolerance.
fn pixels_over(a: &ProbeImage, b: &ProbeImage) -> usize {
    a.rgba.chunks(4).zip(b.rgba.chunks(4)).filter(|(x, y)| x.iter().zip(y.iter()).any(|(p, q)| p.abs_diff(*q) > CHANNEL_TOLERANCE)).count()
}

/// Whether the picture shows nothing but the clear colour and at most one
/// other: what the program draws does not vary.
fn is_constant(a: &ProbeImage) -> bool {
    let colours: std::collections::BTreeSet<&[u8]> = a.rgba.chunks(4).collect();
    colours.len() <= 2
}

#[test]
fn either_stage_swaps_with_daslangs_generator() {
    let Some((tutorials, peer)) = reference() else { return };
    let profiles = pairs(&tutorials, &peer);
    // The two contexts draw at once, each on a thread of its own.
    let results: Vec<(Vec<String>, usize, u8)> = std::thread::scope(|scope| {
        let runs: Vec<_> = [Consumer::Gl330, Consumer::Gles300].into_iter().zip(&profiles).map(|(c, all)| scope.spawn(move || mix_profile(c, all))).collect();
        runs.into_iter().map(|r| r.join().expect("a profile's thread")).collect()
    });
    let failures: Vec<String> = results.iter().flat_map(|(f, ..)| f.iter().cloned()).collect();
    let draws: usize = results.iter().map(|(_, d, _)| d).sum();
    let worst = results.iter().map(|r| r.2).max().unwrap_or(0);
    assert!(failures.is_empty(), "{} of the mixes fail:\n{}", failures.len(), failures.join("\n"));
    eprintln!("{draws} probe draws; the largest channel difference of a mix from what it must draw: {worst}/255");
}

/// Draws every program of one profile and its two mixes on `consumer`:
/// the failures, the number of draws (none without the context) and the
/// largest channel difference of a mix from what it must draw.
fn mix_profile(consumer: Consumer, all: &[Pair]) -> (Vec<String>, usize, u8) {
    let mut failures = Vec::new();
    let mut draws = 0;
    let mut worst = 0;
    let Some(gl) = support::gpu::gl(consumer) else { return (failures, draws, worst) };
    assert_eq!(all.len(), 31, "the tutorials' 31 programs");
    for (stem, vs, fs, ours, theirs) in all {
        let what = |mix: &str| format!("{} {stem} {vs}+{fs} ({mix})", consumer.name());
        let own = match gl.probe(&ours[0], &ours[1], SIZE) {
            Ok(i) => i,
            Err(e) => {
                failures.push(format!("{}: {e}", what("umbrac's pair")));
                continue;
            }
        };
        draws += 1;
        if is_constant(&own) != CONSTANT.contains(&(stem.as_str(), fs.as_str())) {
            failures.push(format!("{}: the picture is {}constant", what("umbrac's pair"), if is_constant(&own) { "" } else { "not " }));
        }
        // What a mix with daslang's fragment stage must draw.
        let rounds = PEER_ROUNDS.contains(&(stem.as_str(), fs.as_str()));
        let peer = if rounds {
            match gl.probe(&theirs[0], &theirs[1], SIZE) {
                Ok(p) => {
                    draws += 1;
                    if pixels_over(&own, &p) <= PIXELS_OVER {
                        failures.push(format!("{}: daslang's pair draws umbrac's picture; drop it from PEER_ROUNDS", what("daslang's pair")));
                    }
                    p
                }
                Err(e) => {
                    failures.push(format!("{}: {e}", what("daslang's pair")));
                    continue;
                }
            }
        } else {
            own.clone()
        };
        for (mix, v, f, expect) in [("umbrac's vertex, daslang's fragment", &ours[0], &theirs[1], &peer), ("daslang's vertex, umbrac's fragment", &theirs[0], &ours[1], &own)] {
            match gl.probe(v, f, SIZE) {
                Ok(image) => {
                    draws += 1;
                    let over = pixels_over(expect, &image);
                    worst = expect.rgba.iter().zip(&image.rgba).map(|(a, b)| a.abs_diff(*b)).fold(worst, u8::max);
                    if over > PIXELS_OVER {
                        failures.push(format!("{}: {over} of {} pixels differ by more than {CHANNEL_TOLERANCE}", what(mix), SIZE * SIZE));
                    }
                }
                Err(e) => failures.push(format!("{}: {e}", what(mix))),
            }
        }
    }
    (failures, draws, worst)
}

/// The probe tells pictures apart: a fragment shader that differs by a
/// constant draws another picture, and one that writes a constant a
/// constant one.
#[test]
fn the_probe_sees_a_changed_shader() {
    let Some(gl) = support::gpu::gl(Consumer::Gl330) else { return };
    let vs = "#version 330 core\nin vec3 a_pos;\nout vec2 v;\nvoid main() { v = a_pos.xy; gl_Position = vec4(a_pos, 1.0); }\n";
    let fs = |k: &str| format!("#version 330 core\nin vec2 v;\nuniform float u_k;\nout vec4 c;\nvoid main() {{ c = vec4(v * 0.5 + 0.5, u_k * {k}, 1.0); }}\n");
    let a = gl.probe(vs, &fs("1.0"), SIZE).unwrap();
    assert_eq!(a, gl.probe(vs, &fs("1.0"), SIZE).unwrap(), "the probe is deterministic");
    assert!(!is_constant(&a));
    assert!(pixels_over(&a, &gl.probe(vs, &fs("0.5"), SIZE).unwrap()) > PIXELS_OVER);
    let flat = "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(0.25); }\n";
    assert!(is_constant(&gl.probe(vs, flat, SIZE).unwrap()));
    // Why umbrac writes no `smooth`: Mesa refuses a qualifier on one side
    // only (GLSL 4.30's rule, which it applies to 3.30 as well).
    let smooth = "#version 330 core\nsmooth in vec2 v;\nout vec4 c;\nvoid main() { c = vec4(v, 0.0, 1.0); }\n";
    assert!(matches!(gl.probe(vs, smooth, SIZE), Err(umbrac::render::exec::ExecError::Link { .. })));
}

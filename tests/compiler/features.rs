//! The feature matrix in docs/features.md is checked against the compiler:
//! every row names a snippet here, every snippet has a row, and each
//! target column says what compiling the snippet for that target does:
//! `yes` (compiles, passes the validators), `lowered` (compiles and
//! validates, by a lowering the notes column describes) or `no` (a compile
//! error, never an internal one). Some rows also assert a property of the
//! output (`NEEDLES`).

use crate::support;

use std::collections::BTreeMap;
use std::path::Path;

use umbrac::Target;

/// A fragment entry point writing `f_color`, after `decls`.
fn frag(decls: &str, body: &str) -> String {
    format!("{decls}\nvar @out f_color : float4\n[fragment_program]\ndef fs {{\n{body}\n}}\n")
}

/// A vertex entry point, after `decls`.
fn vert(decls: &str, body: &str) -> String {
    format!("{decls}\n[vertex_program]\ndef vs {{\n{body}\n    gl_Position = float4(0.0, 0.0, 0.0, 1.0)\n}}\n")
}

fn snippets() -> BTreeMap<&'static str, String> {
    let mut m = BTreeMap::new();
    let mut add = |id: &'static str, src: String| {
        assert!(m.insert(id, src).is_none(), "snippet `{id}` twice");
    };
    // ---------------------------------------------------------------- types
    add("scalars-vectors", frag("", "    let a = 1.0\n    let b = int3(1, 2, 3)\n    let c = uint2(1u)\n    let d = bool4(true, false, true, a > 0.5)\n    f_color = float4(float(b.x + int(c.y)), a, any(d) ? 1.0 : 0.0, 1.0)"));
    add("matrices", frag("", "    let m2 = float2x2(1.0)\n    let m3 = float3x3(2.0)\n    let m4 = float4x4(1.0)\n    let m43 = float4x3(1.0)\n    let v = m43 * float4(1.0)\n    f_color = m4 * float4(m3 * float3(m2 * float2(1.0), 1.0) + v, 1.0) * determinant(m3) + float4(transpose(m4)[1])"));
    add("structs", frag("struct S {\n    a : float3\n    b : int\n}\ndef make(x : float) : S {\n    return S(float3(x), 2)\n}", "    var s = make(0.5)\n    s.b += 1\n    f_color = float4(s.a, float(s.b))"));
    add("fixed-arrays", frag("var @uniform u_i : int", "    var a : float[4]\n    a[u_i] = 1.0\n    let b = fixed_array<float>(1.0, 2.0)\n    f_color = float4(a[u_i & 3] + b[u_i & 1])"));
    add("constant-arrays", frag("let K = fixed_array<float3>(float3(1.0), float3(0.5))\nvar @uniform u_i : int", "    f_color = float4(K[u_i], 1.0)"));
    add("sampler-types", frag("var @uniform a : sampler2D\nvar @uniform b : sampler2DShadow\nvar @uniform c : sampler2DArray\nvar @uniform d : sampler2DArrayShadow\nvar @uniform e : sampler3D\nvar @uniform f : samplerCube\nvar @uniform g : samplerCubeShadow\nvar @uniform h : isampler2D\nvar @uniform i : usampler2D", "    let uv = float2(0.5)\n    let s = textureCompare(b, uv, 0.5) + textureCompare(d, float3(uv, 1.0), 0.5) + textureCompare(g, float3(1.0), 0.5)\n    let n = float(texelFetch(h, int2(0), 0).x) + float(texelFetch(i, int2(0), 0).x)\n    f_color = texture(a, uv) + texture(c, float3(uv, 1.0)) + texture(e, float3(0.5)) + texture(f, float3(1.0)) + float4(s + n)"));
    add("sampler-arrays", frag("var @uniform @stage = 1 layers : sampler2D[3]", "    f_color = texture(layers[0], float2(0.5)) + texture(layers[2], float2(0.5))"));
    add("sampler-arrays-dynamic", frag("var @uniform layers : sampler2D[3]\nvar @uniform u_i : int", "    f_color = texture(layers[u_i], float2(0.5))"));
    add("sampler-parameters", frag("var @uniform t : sampler2D\ndef get(s : sampler2D) : float4 {\n    return texture(s, float2(0.5))\n}", "    f_color = get(t)"));
    // ---------------------------------------------------------------- uniforms
    add("uniform-struct", frag("struct L {\n    dir : float3\n    k : float\n    color : float4\n}\nvar @uniform light : L", "    f_color = light.color * light.k + float4(light.dir, 0.0)"));
    add("uniform-float3x3", frag("var @uniform u_n : float3x3", "    f_color = float4(u_n * float3(1.0), 1.0)"));
    add("uniform-float4-array", frag("var @uniform u_k : float4[8]\nvar @uniform u_i : int", "    f_color = u_k[u_i]"));
    add("uniform-struct-array", frag("struct L {\n    pos : float3\n    r : float\n}\nvar @uniform u_l : L[4]\nvar @uniform u_i : int", "    f_color = float4(u_l[u_i].pos, u_l[3].r)"));
    add("uniform-loose", frag("var @uniform u_a : float4\nvar @uniform u_m : float4x4", "    f_color = u_m * u_a"));
    add("uniform-scalar-array", frag("var @uniform u_w : float[4]\nvar @uniform u_v : float2[2]\nvar @uniform u_i : int", "    f_color = float4(u_w[u_i], u_w[0], u_v[u_i])"));
    add("uniform-bool", frag("var @uniform u_b : bool\nvar @uniform u_b2 : bool2", "    f_color = float4(u_b ? 1.0 : 0.0, u_b2.y ? 1.0 : 0.0, 0.0, 1.0)"));
    add("uniform-float2x2", frag("var @uniform u_m : float2x2\nvar @uniform u_n : float3x2", "    f_color = float4(u_m[0], u_n[2])"));
    add("uniform-struct-whole", frag("struct F {\n    c : float4\n}\nstruct S {\n    m : float3x3\n    f : F[2]\n    g : F\n}\nvar @uniform u_s : S\ndef tint(s : S) : float4 {\n    return s.g.c + s.f[1].c\n}", "    let s = u_s\n    f_color = tint(u_s) + float4(s.m * s.f[0].c.xyz, 1.0)"));
    add("uniform-struct-scalar-array", frag("struct S {\n    w : float[4]\n}\nvar @uniform u_s : S", "    f_color = float4(u_s.w[0])"));
    add("uniform-struct-bool", frag("struct S {\n    b : bool\n}\nvar @uniform u_s : S", "    f_color = float4(u_s.b ? 1.0 : 0.0)"));
    add("uniform-struct-float2x2", frag("struct S {\n    m : float2x2\n}\nvar @uniform u_s : S", "    f_color = float4(u_s.m[0], u_s.m[1])"));
    add("uniform-unpadded-nested-struct", frag("struct In {\n    a : float\n}\nstruct Out {\n    i : In\n    b : float\n}\nvar @uniform u : Out", "    f_color = float4(u.i.a + u.b)"));
    // ---------------------------------------------------------------- statements
    add("let-var", frag("", "    let a = 1.0\n    var b : float\n    var c, d = 2.0\n    b = a + c + d\n    f_color = float4(b)"));
    add("assignment-operators", frag("var @uniform u_i : int", "    var x = u_i\n    x += 1\n    x -= 2\n    x *= 3\n    x /= 2\n    x %= 5\n    x &= 7\n    x |= 8\n    x ^= 1\n    x <<= 2\n    x >>= 1\n    x++\n    x--\n    var v = float3(1.0)\n    v.xz *= 2.0\n    f_color = float4(v, float(x))"));
    add("control-flow", frag("var @uniform u_i : int", "    var s = 0.0\n    if (u_i == 0) {\n        s = 1.0\n    } elif (u_i == 1) {\n        s = 2.0\n    } else {\n        s = 3.0\n    }\n    var k = 0\n    while (k < 10) {\n        k++\n        if (k == 3) {\n            continue\n        }\n        if (k > u_i) {\n            break\n        }\n    }\n    for (i in range(4)) {\n        s += float(i)\n    }\n    for (j in range(2, u_i)) {\n        s += float(j)\n    }\n    f_color = float4(s + float(k))"));
    add("discard", frag("var @uniform u_a : float", "    if (u_a < 0.5) {\n        discard()\n    }\n    f_color = float4(u_a)"));
    add("discard-in-vertex", vert("", "    discard()"));
    add("recursion", frag("def f(x : int) : int {\n    return x > 0 ? f(x - 1) : 0\n}", "    f_color = float4(float(f(3)))"));
    // ---------------------------------------------------------------- expressions
    add("arithmetic", frag("var @uniform u_v : float3", "    let a = u_v * 2.0 + u_v / float3(3.0) - float3(1.0)\n    f_color = float4(-a, 1.0)"));
    add("integer-division-remainder", frag("var @uniform u_i : int", "    let q = u_i / -3\n    let r = u_i % -3\n    f_color = float4(float(q), float(r), 0.0, 1.0)"));
    add("float-remainder", frag("var @uniform u_x : float", "    f_color = float4(u_x % 2.0, mod(u_x, 3.0), -7.5 % 2.0, 1.0)"));
    add("comparison-logic", frag("var @uniform u_x : float", "    let a = u_x < 1.0 && !(u_x >= 3.0) || u_x == 2.0 ^^ u_x != 4.0\n    let v = float2(u_x) == float2(1.0)\n    f_color = float4(a ? 1.0 : 0.0, v ? 1.0 : 0.0, 0.0, 1.0)"));
    add("bitwise-shifts", frag("var @uniform u_i : int3\nvar @uniform u_u : uint", "    let a = (u_i & int3(3)) | ~u_i ^ (u_i << int3(1)) >> int3(2)\n    let b = (u_u << 3) >> 1u\n    f_color = float4(float3(a), float(b))"));
    add("ternary-scalar-condition", frag("var @uniform u_x : float", "    f_color = u_x > 0.5 ? float4(1.0) : float4(0.0)"));
    add("ternary-vector-float", frag("var @uniform u_v : float4", "    f_color = greaterThan(u_v, float4(0.5)) ? u_v : float4(0.0)"));
    add("ternary-vector-int-bool", frag("var @uniform u_v : int4", "    let c = lessThan(u_v, int4(0))\n    let n = c ? -u_v : u_v\n    let b = c ? not(c) : c\n    f_color = float4(n) + float4(float(any(b)))"));
    add("swizzles", frag("var @uniform u_v : float4", "    var v = u_v.wzyx\n    v.xy = u_v.rg\n    v.z = u_v.p\n    f_color = v"));
    add("matrix-dynamic-index", frag("var @uniform u_i : int", "    let m = float3x3(2.0)\n    var n = float4x4(1.0)\n    n[u_i] = float4(0.5)\n    f_color = float4(m[u_i], 1.0) + n[u_i]"));
    add("constructors-casts", frag("var @uniform u_i : int2", "    let a = float2(u_i.x, u_i.y)\n    let b = float4(a, 1.0, 2.0)\n    let c = float3(b)\n    let d = int(c.x) + int(uint(u_i.y))\n    f_color = float4(c, float(d))"));
    add("non-finite-constant", frag("let K = 1.0 / 0.0", "    f_color = float4(K)"));
    add("undefined-constant-subexpression", frag("var @uniform u_x : float", "    f_color = float4(u_x + sqrt(-1.0))"));
    add("constant-zero-divisor", frag("var @uniform u_i : int", "    f_color = float4(float(u_i / 0))"));
    add("scalar-geometric-builtins", frag("var @uniform u_x : float", "    f_color = float4(dot(u_x, u_x))"));
    add("arrays-of-arrays", frag("", "    var a : float[2][2]\n    f_color = float4(a[0][1])"));
    add("implicit-conversion", frag("var @uniform u_x : float", "    f_color = float4(u_x * 2)"));
    // ---------------------------------------------------------------- builtins
    add("math-builtins", frag("var @uniform u_x : float3", "    let a = sin(u_x) + cos(u_x) + tan(u_x) + asin(u_x) + acos(u_x) + atan(u_x) + atan2(u_x, u_x) + sinh(u_x) + cosh(u_x) + tanh(u_x)\n    let b = radians(u_x) + degrees(u_x) + exp(u_x) + exp2(u_x) + log(u_x) + log2(u_x) + sqrt(u_x) + inversesqrt(u_x) + rsqrt(u_x)\n    let c = floor(u_x) + ceil(u_x) + fract(u_x) + trunc(u_x) + round(u_x) + roundEven(u_x) + abs(u_x) + sign(u_x) + min(u_x, 0.5) + max(u_x, u_x) + clamp(u_x, 0.0, 1.0)\n    let d = mix(u_x, a, 0.5) + lerp(a, b, c) + step(0.5, u_x) + smoothstep(0.0, 1.0, u_x) + pow(u_x, b) + mod(u_x, 2.0) + fma(a, b, c) + saturate(u_x) + rcp(u_x)\n    let e = length(u_x) + distance(u_x, a) + dot(u_x, b)\n    let f = cross(a, b) + normalize(u_x) + reflect(u_x, b) + refract(u_x, b, 0.5) + faceforward(a, b, c)\n    let g = all(lessThanEqual(a, b)) && !any(equal(a, b)) || any(notEqual(a, c)) || all(greaterThanEqual(b, c)) || any(greaterThan(a, c))\n    f_color = float4(d + f + float3(e), g ? 1.0 : 0.0)"));
    add("integer-builtins", frag("var @uniform u_i : int2", "    let a = abs(u_i) + sign(u_i) + min(u_i, 3) + max(u_i, int2(1)) + clamp(u_i, 0, 5)\n    f_color = float4(float2(a), 0.0, 1.0)"));
    add("bit-casts", frag("var @uniform u_x : float2", "    let a = floatBitsToInt(u_x)\n    let b = floatBitsToUint(u_x.x)\n    f_color = float4(intBitsToFloat(a), uintBitsToFloat(b), 1.0)"));
    add("derivatives", frag("var @uniform u_x : float", "    let v = float2(u_x)\n    f_color = float4(dFdx(v), dFdy(u_x), fwidth(u_x))"));
    add("derivatives-in-vertex", vert("var @uniform u_x : float\nvar @inout v_x : float", "    v_x = dFdx(u_x)"));
    add("texture-functions", frag("var @uniform t : sampler2D\nvar @uniform s : sampler2DShadow\nvar @inout v_uv : float2", "    let a = texture(t, v_uv) + texture(t, v_uv, 1.0) + textureLod(t, v_uv, 2.0) + textureGrad(t, v_uv, dFdx(v_uv), dFdy(v_uv))\n    let b = textureProj(t, float3(v_uv, 2.0)) + textureProj(t, float4(v_uv, 0.0, 2.0)) + texelFetch(t, int2(1), 0)\n    let c = textureCompare(s, v_uv, 0.5) + textureProj(s, float4(v_uv, 0.5, 1.0))\n    let d = textureSize(t, 0)\n    f_color = a + b + float4(c + float(d.x))"));
    add("texture-in-vertex", vert("var @uniform t : sampler2D\nvar @uniform s : sampler2DShadow\nvar @inout v_x : float", "    v_x = texture(t, float2(0.5)).x + texture(t, float2(0.5), 1.0).y + textureCompare(s, float2(0.5), 0.5)"));
    add("nonuniform-sampling", frag("var @uniform t : sampler2D\nvar @inout v_uv : float2", "    if (v_uv.x < 0.5) {\n        discard()\n    }\n    var c = float4(0.0)\n    while (c.x < 1.0) {\n        c += texture(t, v_uv + c.xy)\n    }\n    f_color = c"));
    add("inverse", frag("var @uniform u_m : float4x4\nvar @uniform u_n : float3x3", "    f_color = inverse(u_m)[0] + float4(inverse(u_n)[1], inverse(float2x2(2.0))[0].x)"));
    add("isnan-isinf", frag("var @uniform u_x : float", "    f_color = float4(isnan(u_x) ? 1.0 : 0.0)"));
    add("textureOffset", frag("let D = int2(1, 0)\nvar @uniform t : sampler2D\nvar @uniform s : sampler2DShadow\nvar @uniform a : sampler2DArray\nvar @uniform v : sampler3D", "    f_color = textureOffset(t, float2(0.5), int2(1, 0)) + textureOffset(t, float2(0.5), -D, 1.0) + textureLodOffset(a, float3(0.5), 0.0, int2(-8, 7)) + textureOffset(v, float3(0.5), int3(1)) + float4(textureCompareOffset(s, float2(0.5), 0.5, D))"));
    add("texelFetchOffset", frag("var @uniform t : sampler2D", "    f_color = texelFetchOffset(t, int2(4), 0, int2(1, -1))"));
    add("textureOffset-varying", frag("var @uniform t : sampler2D\nvar @uniform u_d : int2", "    f_color = textureOffset(t, float2(0.5), u_d)"));
    add("unknown-builtin", frag("", "    f_color = float4(normalise(float3(1.0)), 1.0)"));
    // ---------------------------------------------------------------- builtin variables
    add("gl_Position-gl_VertexID-gl_InstanceID", "[vertex_program]\ndef vs {\n    gl_Position = float4(float(gl_VertexID), float(gl_InstanceID), float(gl_VertexIndex + gl_InstanceIndex), 1.0)\n}\n".to_string());
    add("gl_FragCoord-gl_FrontFacing-gl_FragDepth", frag("", "    gl_FragDepth = gl_FragCoord.z\n    f_color = gl_FrontFacing ? float4(1.0) : gl_FragCoord"));
    add("gl_PointSize", vert("var @uniform u_s : float", "    gl_PointSize = u_s"));
    add("gl_PointCoord", frag("", "    f_color = float4(gl_PointCoord, 0.0, 1.0)"));
    add("builtin-in-wrong-stage", frag("", "    f_color = float4(float(gl_VertexID))"));
    // ---------------------------------------------------------------- interface
    add("attributes-varyings-locations", "var @in @location = 3 a_pos : float3\nvar @in a_uv : float2\nvar @inout v_uv : float2\nvar @inout @location = 2 v_id : int\nvar @out f_color : float4\n[vertex_program(name = \"main_vs\")]\ndef v {\n    v_uv = a_uv\n    v_id = 1\n    gl_Position = float4(a_pos, 1.0)\n}\n[fragment_program]\ndef fs {\n    f_color = float4(v_uv, float(v_id), 1.0)\n}\n".to_string());
    add("multiple-render-targets", "var @out @location = 0 g0 : float4\nvar @out @location = 1 g1 : float4\nvar @out @location = 2 g2 : uint4\n[fragment_program]\ndef fs {\n    g0 = float4(1.0)\n    g1 = float4(0.5)\n    g2 = uint4(1u)\n}\n".to_string());
    add("vertex-out", vert("var @out @location = 1 o_pos : float3\nvar @out @location = 2 o_id : int", "    o_pos = float3(1.0)\n    o_id = gl_VertexID"));
    add("location-clash", vert("var @inout @location = 1 v_a : float\nvar @out @location = 1 o_b : float", "    v_a = 1.0\n    o_b = 2.0"));
    add("texture-units", frag("var @uniform @stage = 3 a : sampler2D\nvar @uniform b : sampler2D", "    f_color = texture(a, float2(0.5)) + texture(b, float2(0.5))"));
    // ---------------------------------------------------------------- programs and module state
    add("programs-per-file", "var @in @location = 0 a_pos : float3\nvar @out tf_pos : float3\n[vertex_program]\ndef sim_vs {\n    tf_pos = a_pos\n}\nvar @in @location = 0 q_pos : float2\nvar @inout v_uv : float2\nvar @uniform @stage = 0 a : sampler2D\nvar @out f_color : float4\n[vertex_program]\ndef quad_vs {\n    v_uv = q_pos\n    gl_Position = float4(q_pos, 0.0, 1.0)\n}\n[fragment_program]\ndef quad_fs {\n    f_color = texture(a, v_uv)\n}\nvar @uniform @stage = 0 b : sampler2D\nvar @out f_other : float4\n[fragment_program]\ndef other_fs {\n    f_other = texture(b, v_uv)\n}\n".to_string());
    add("bare-stage", frag("var @uniform @stage t : sampler2D", "    f_color = texture(t, float2(0.5))"));
    add("module-variables", frag("var angle = 0.25\nvar {\n    count : int\n}\ndef step() {\n    count++\n    angle *= 2.0\n}", "    step()\n    f_color = float4(angle, float(count), 0.0, 1.0)"));
    add("let-blocks", frag("let {\n    A = 1.0; B = A * 2.0\n    C : float3 = float3(B)\n}", "    f_color = float4(C, A)"));
    add("uniform-defaults", frag("struct G {\n    lift : float3\n    gamma : float\n}\nvar @uniform u_k : float = 0.5\nvar @uniform u_g : G = G(float3(0.1), 2.2)", "    f_color = float4(u_g.lift * u_k, u_g.gamma)"));
    add("bind-groups", frag("var @uniform @set = 1 @binding = 2 u_a : float4\nvar @uniform @set = 1 t : sampler2D\nvar @uniform u_b : float4", "    f_color = u_a + u_b + texture(t, float2(0.5))"));
    add("push-constant", frag("var @push_constant pc_tint : float4", "    f_color = pc_tint"));
    gl_dialect(&mut add);
    vulkan_dialect(&mut add);
    compute(&mut add);
    functions_and_data(&mut add);
    for (id, src) in snippets_language_l() {
        add(id, src);
    }
    m
}

/// Functions and data as daslang writes them (issue 17): results from
/// `return`, defaults, parameter kinds, overloads, pipes, `with`, enums,
/// construction by field name, `for` over arrays.
/// Compute rows: the table with `glsl430` and `gles310` columns.
fn compute(add: &mut impl FnMut(&'static str, String)) {
    let buf = "struct Buf {\n    count : uint\n    data : float[]\n}\n";
    add("compute-program", format!("{buf}var @ssbo out_buf : Buf\n[compute_program(local_size_x = 8, local_size_y = 2, version = 430)]\ndef cs {{\n    let i = gl_GlobalInvocationID.x + gl_NumWorkGroups.x * gl_WorkGroupSize.x * gl_GlobalInvocationID.y\n    out_buf.data[i] = float(gl_LocalInvocationID.x + gl_WorkGroupID.y + gl_LocalInvocationIndex)\n}}\n"));
    add("ssbo", format!("{buf}var @ssbo @readonly src : Buf\nvar @ssbo dst : Buf\n[compute_program(local_size_x = 64)]\ndef cs {{\n    let i = gl_GlobalInvocationID.x\n    if (i < src.count && i < length(dst.data)) {{\n        dst.data[i] = src.data[i] * 2.0\n    }}\n}}\n"));
    add("ssbo-fragment", frag("struct P {\n    v : float4\n}\nvar @ssbo @readonly buf : P", "    f_color = buf.v"));
    add("groupshared", format!("{buf}var @ssbo b : Buf\nvar @groupshared tile : float[64]\n[compute_program(local_size_x = 64)]\ndef cs {{\n    let l = gl_LocalInvocationIndex\n    tile[l] = b.data[gl_GlobalInvocationID.x]\n    barrier()\n    memoryBarrierShared()\n    groupMemoryBarrier()\n    b.data[gl_GlobalInvocationID.x] = tile[63u - l]\n}}\n"));
    add("atomics", "struct H {\n    total : uint\n    low : int\n    bins : uint[]\n}\nvar @ssbo h : H\nvar @groupshared n : uint\n[compute_program(local_size_x = 64)]\ndef cs {\n    let i = gl_GlobalInvocationID.x\n    atomicAdd(h.bins[i % 16u], 1u)\n    atomicMin(h.low, int(i))\n    let old = atomicCompSwap(h.total, 0u, 1u)\n    atomicExchange(n, old)\n    atomicOr(n, atomicXor(h.total, atomicAnd(n, 3u)))\n    atomicMax(h.total, n)\n}\n".to_string());
    add("storage-images", "var @writeonly @format = rgba8 dst : image2D\nvar @readonly @format = rgba16f src : image3D\nvar @format = r32ui counts : uimage2D\nvar @readonly @format = r32f layers : image2DArray\n[compute_program(local_size_x = 8, local_size_y = 8)]\ndef cs {\n    let p = int2(gl_GlobalInvocationID.xy)\n    let c = imageLoad(counts, p)\n    imageStore(counts, p, c + uint4(1u))\n    let l = imageLoad(layers, int3(p, 1))\n    imageStore(dst, p % imageSize(dst), imageLoad(src, int3(p, 0)) + l)\n}\n".to_string());
    add("storage-units", "struct B {\n    data : uint[]\n}\nvar @uniform@format@stage@writeonly c_dst : image2D\nvar @readonly @format = \"r32f\" @stage = 2 c_src : image2D\nvar @ssbo @stage = 3 buf : B\n[compute_program(local_size_x = 8, local_size_y = 8)]\ndef cs {\n    let p = int2(gl_GlobalInvocationID.xy)\n    buf.data[0] = uint(p.x)\n    imageStore(c_dst, p, imageLoad(c_src, p))\n}\n".to_string());
    add("read-write-image-any-format", "var @uniform@format c_img : image2D\n[compute_program(local_size_x = 8, local_size_y = 8)]\ndef cs {\n    let p = int2(gl_GlobalInvocationID.xy)\n    imageStore(c_img, p, imageLoad(c_img, p) * 0.5)\n}\n".to_string());
    dasspirv_builtins(add);
    add("barrier-uniformity", format!("{buf}var @ssbo b : Buf\n[compute_program(local_size_x = 64)]\ndef cs {{\n    if (b.data[gl_GlobalInvocationID.x] > 0.0) {{\n        barrier()\n    }}\n}}\n"));
}

/// daslang's GL dialect as it spells it (issue 35): one-line bodies,
/// `unroll`, `reinterpret`, the CPU-only names, `@stage`/`@format` on
/// storage resources.
fn gl_dialect(add: &mut impl FnMut(&'static str, String)) {
    add("one-line-bodies", frag("var @uniform u_i : int\ndef pick(x : int) : float {\n    if (x < 0) return 0.0\n    elif (x == 0) return 0.5\n    return 1.0\n}", "    var s = 0.0\n    var k = 0\n    if (u_i > 2) s = 1.0 else s = 2.0\n    while (k < u_i) k++\n    for (i in range(4)) s += float(i)\n    for (i in range(8)) {\n        if (i > u_i) break\n        if (i == 1) continue\n        s += 1.0\n    }\n    f_color = float4(s + float(k) + pick(u_i))"));
    add("unroll", frag("let N = 3\nvar @uniform u_w : float4[4]", "    var s = float4(0.0)\n    unroll() $ {\n        for (i in range(N)) {\n            s += u_w[i]\n        }\n    }\n    unroll($ {\n        for (i in range(1, 4)) {\n            s *= u_w[i]\n        }\n    })\n    f_color = s"));
    add("unroll-not-constant", frag("var @uniform u_n : int", "    var s = 0.0\n    unroll() $ {\n        for (i in range(u_n)) {\n            s += 1.0\n        }\n    }\n    f_color = float4(s)"));
    add("call-with-block", frag("", "    var s = 0.0\n    invoke() $ {\n        s = 1.0\n    }\n    f_color = float4(s)"));
    add("reinterpret", frag("var @uniform u_x : float2", "    let u = unsafe(reinterpret<uint2>(u_x))\n    let i = reinterpret<int>(u_x.y)\n    f_color = float4(reinterpret<float2>(u ^ uint2(1u)), unsafe(reinterpret<float>(i)), 1.0)"));
    add("reinterpret-other-sizes", frag("var @uniform u_x : float2", "    f_color = float4(reinterpret<uint>(u_x))"));
    add("cpu-only-lattice", frag("", "    let b = byte8(1)\n    var h : half8\n    f_color = float4(1.0)"));
    add("cpu-only-calls", frag("", "    var v = float4(1.0)\n    memzero(v)\n    f_color = v"));
    add("host-expressions", frag("", "    var a = 1.0\n    let b = cast<int> a\n    f_color = float4(a ?? 2.0)"));
}

/// daslang's Vulkan dialect (issue 36): its stages, resources at
/// `@set`/`@binding`, push constants, stage I/O by location, `@flat`; the
/// stages umbrac does not compile, refused. Rows of the compute table's
/// shape (six targets).
fn vulkan_dialect(add: &mut impl FnMut(&'static str, String)) {
    let pair = |vs_decls: &str, vs_body: &str, fs_decls: &str, fs_body: &str| {
        format!("{vs_decls}\n[vulkan_vertex_shader(name=\"v\")]\ndef vs {{\n{vs_body}\n    gl_Position = float4(0.0, 0.0, 0.0, 1.0)\n}}\n{fs_decls}\nvar @out @location = 0 o_color : float4\n[fragment_shader]\ndef fs {{\n{fs_body}\n}}\n")
    };
    add("vulkan-stages", pair("var @in @location = 0 a_pos : float3\nvar @out @location = 1 v_n : float3", "    v_n = a_pos", "var @in @location = 1 f_n : float3", "    o_color = float4(f_n, 1.0)"));
    add("vulkan-flat", pair("var @out @flat @location = 0 v_w : float\nvar @out @location = 1 v_id : int", "    v_w = 1.0\n    v_id = gl_VertexIndex", "var @in @flat @location = 0 f_w : float\nvar @in @location = 1 f_id : int", "    o_color = float4(f_w, float(f_id), 0.0, 1.0)"));
    add("vulkan-location-mismatch", pair("var @out @location = 0 v_n : float3", "    v_n = float3(1.0)", "var @in @location = 0 f_n : float2", "    o_color = float4(f_n, 0.0, 1.0)"));
    add("vulkan-resources", pair("struct Cam {\n    vp : float4x4\n}\nvar @uniform @set = 0 @binding = 0 cam : Cam", "    let p = cam.vp * float4(1.0)\n    v_p = p.x", "var @set = 0 @binding = 1 tex : sampler2D\nvar @uniform @set = 1 @binding = 0 depth : sampler2DShadow\nvar @in @location = 0 f_p : float", "    o_color = texture(tex, float2(f_p)) * textureCompare(depth, float2(0.5), f_p)").replace("[vulkan_vertex_shader", "var @out @location = 0 v_p : float\n[vulkan_vertex_shader"));
    add("vulkan-push-constant", pair("struct Push {\n    model : float4x4\n    tint : float4\n}\nvar @push_constant pc : Push\nvar @out @location = 0 v_c : float4", "    v_c = pc.model * pc.tint", "var @in @location = 0 f_c : float4", "    o_color = f_c * pc.tint"));
    add("vulkan-compute", "struct P {\n    pos : float4\n}\nvar @ssbo @set = 0 @binding = 0 ps : array<P>\nvar @writeonly @set = 0 @binding = 1 img : image2D\nvar @ssbo @set = 0 @binding = 2 n : array<uint>\n[vulkan_compute_shader(local_size_x=64)]\ndef cs {\n    let i = gl_GlobalInvocationID.x\n    ps[i].pos += float4(1.0)\n    atomicAdd(n[0], 1u)\n    imageStore(img, int2(int(i), 0), ps[i].pos)\n}\n".to_string());
    add("vulkan-descriptor-array", pair("var @out @flat @location = 0 v_m : int", "    v_m = gl_InstanceIndex", "var @set = 0 @binding = 0 ts : sampler2D[4]\nvar @in @flat @location = 0 f_m : int", "    o_color = texture(ts[nonuniformEXT(f_m)], float2(0.5)) + texture(ts[1], float2(0.5))"));
    add("vulkan-mesh-task-stages", "struct P {\n    k : uint\n}\nvar @task_payload payload : P\n[vulkan_task_shader(local_size_x=1)]\ndef ts {\n    payload.k = 2u\n    EmitMeshTasksEXT(payload.k, 1u, 1u)\n}\nvar @out @location = 0 m_c : array<float>\n[vulkan_mesh_shader(local_size_x=1, max_vertices=3, max_primitives=1)]\ndef ms {\n    SetMeshOutputsEXT(3u, 1u)\n    for (i in range(3)) {\n        gl_MeshVerticesEXT[i].gl_Position = float4(float(i), float(payload.k), 0.0, 1.0)\n        m_c[i] = float(gl_WorkGroupID.x)\n    }\n    gl_PrimitiveTriangleIndicesEXT[0] = uint3(0u, 1u, 2u)\n}\nvar @in @location = 0 f_c : float\nvar @out @location = 0 o_color : float4\n[fragment_shader]\ndef fs {\n    o_color = float4(f_c)\n}\n".to_string());
    add("vulkan-ray-tracing-stages", "[vulkan_raygen_shader(name=\"rgen\")]\ndef rgen {\n    let g = gl_LaunchIDEXT\n}\n".to_string());
}

fn functions_and_data(add: &mut impl FnMut(&'static str, String)) {
    add("inferred-result", frag("def half_of(x : float) {\n    return x * 0.5\n}\ndef twice(x : float) => x * 2.0\ndef third(x : float) -> float {\n    return x / 3.0\n}\ndef nothing(x : float) : void {\n    return\n}", "    nothing(1.0)\n    f_color = float4(half_of(1.0), twice(0.25), third(1.5), 1.0)"));
    add("default-parameters", frag("def tone(x : float; gain : float = 2.0; bias : float3 = float3(0.1)) => x * gain + bias", "    f_color = float4(tone(0.5) + tone(0.5, 1.0) + tone(0.5, 1.0, float3(0.0)), 1.0)"));
    add("named-arguments", frag("def tone(x : float = 1.0; gain : float = 2.0; bias : float3) => x * gain + bias\ndef tone(x : int) => float3(float(x))", "    f_color = float4(tone([bias = float3(0.1), x = 0.5]) + tone([bias = float3(0.0)]) + tone(1), 1.0)"));
    add("named-arguments-unknown", frag("def tone(x : float; gain : float = 2.0) => x * gain", "    f_color = float4(tone([x = 0.5, gian = 1.0]))"));
    add("default-not-constant", frag("var @uniform u_g : float\ndef tone(x : float; gain : float = u_g) => x * gain", "    f_color = float4(tone(0.5))"));
    add("visibility-modifiers", frag("struct private S {\n    a : float\n}\nlet private K = 0.5\nlet private {\n    B = 0.25\n}\nvar private @uniform u_vis : float\nvar shared @uniform u_shared : float\nenum private E {\n    one\n}\ndef private f(s : S) : float {\n    return s.a * K\n}\ndef public g(x : float) => x", "    f_color = float4(g(f(S(1.0))) * B * u_vis * u_shared)"));
    add("var-parameters", frag("def shrink(var x : float) : float {\n    x *= 0.5\n    return x\n}", "    let a = 1.0\n    f_color = float4(shrink(a), a, 0.0, 1.0)"));
    add("var-struct-parameters", frag("struct L {\n    dir : float3\n    k : float\n}\ndef unit(var l : L) {\n    l.dir = normalize(l.dir)\n}\ndef zero(var a : float[2]) {\n    a[0] = 0.0\n}", "    var l = L(float3(2.0), 1.0)\n    unit(l)\n    unit(L(float3(1.0), 2.0))\n    var a = fixed_array(1.0, 2.0)\n    zero(a)\n    f_color = float4(l.dir, a[0] + a[1])"));
    add("reference-parameters", frag("struct S {\n    v : float3\n}\ndef bump(var x : float&; by : float) {\n    x += by\n}\ndef grow(var s : S&) {\n    s.v *= 2.0\n    bump(s.v.x, 1.0)\n}", "    var a = 1.0\n    bump(a, 0.5)\n    var s = S(float3(1.0))\n    grow(s)\n    var arr : float[2]\n    bump(arr[1], a)\n    f_color = float4(s.v, a + arr[1])"));
    add("reference-argument-not-writable", frag("def bump(var x : float&) {\n    x += 1.0\n}", "    let a = 1.0\n    bump(a)\n    f_color = float4(a)"));
    add("const-parameters", frag("def scale(v : float3 const; k : float const&) : float3 {\n    return v * k\n}", "    f_color = float4(scale(float3(1.0), 0.5), 1.0)"));
    add("overloads", frag("def luma(c : float3) => dot(c, float3(0.2126, 0.7152, 0.0722))\ndef luma(c : float4) => luma(c.rgb) * c.a", "    f_color = float4(luma(float3(0.5)), luma(float4(0.5)), 0.0, 1.0)"));
    add("overload-same-parameters", frag("def luma(c : float3) => c.g\ndef luma(rgb : float3) => rgb.r", "    f_color = float4(luma(float3(0.5)))"));
    add("struct-initializer-function", frag("struct Ray {\n    o : float3\n    d : float3\n}\ndef Ray(o, to : float3) : Ray {\n    return Ray(o = o, d = normalize(to - o))\n}", "    let r = Ray(float3(0.0), float3(1.0))\n    f_color = float4(r.d, 1.0)"));
    add("pipes", frag("def tint(c, by : float3) => c * by", "    let c = float3(0.5) |> tint(float3(1.0, 0.5, 0.25)) |> normalize()\n    let d = tint(float3(1.0)) <| c\n    f_color = float4(d, 1.0)"));
    add("postfix-if", frag("def band(x : float) : float {\n    return 0.0 if (x < 0.25)\n    return 1.0 if (x > 0.75) else return 0.5\n}\nvar @uniform u_x : float", "    var s = 0.0\n    for (i in range(8)) {\n        break if (s > u_x)\n        s += band(float(i) / 8.0)\n    }\n    f_color = float4(s)"));
    add("with", frag("struct Light {\n    dir : float3\n    k : float\n}\nvar @uniform u_light : Light", "    var l = u_light\n    with (l) {\n        k *= 2.0\n    }\n    with (u_light) {\n        f_color = float4(dir * l.k, k)\n    }"));
    add("enums", frag("enum Mode {\n    flat\n    lit = 4\n    toon\n}\nenum Bits : uint {\n    a = 1\n    b = 2\n}\nvar @uniform u_m : int\nlet W = fixed_array<float>(0.1, 0.2, 0.3, 0.4, 0.5, 0.6)", "    let m = u_m == 0 ? Mode.flat : Mode.toon\n    let b = m >= Mode.lit ? Bits.b : Bits.a\n    f_color = float4(W[m], float(int(m)), float(uint(b)), m != Mode.flat ? 1.0 : 0.0)"));
    add("enum-uniform", frag("enum Mode {\n    flat\n    lit\n}\nvar @uniform u_mode : Mode", "    f_color = float4(u_mode == Mode.lit ? 1.0 : 0.0)"));
    add("named-struct-construction", frag("struct M {\n    albedo : float3 = float3(0.8)\n    rough = 0.5\n    metal : float\n}", "    let a = M()\n    let b = M(metal = 1.0, albedo = float3(0.1))\n    f_color = float4(a.albedo * a.rough + b.albedo * b.metal, b.rough)"));
    add("for-arrays", frag("var @uniform u_k : float4[3]", "    var acc : float[3]\n    for (a in acc) {\n        a = 0.5\n    }\n    var s = float4(0.0)\n    for (k in u_k) {\n        s += k\n    }\n    for (a in acc) {\n        s.x += a\n    }\n    f_color = s"));
    add("array-length", frag("let K = fixed_array<float>(0.25, 0.5, 0.25)\nlet N = length(K)\nvar @uniform u_k : float4[3]", "    var s = float4(0.0)\n    for (i in range(length(u_k))) {\n        s += u_k[i] * K[i % N]\n    }\n    f_color = s"));
    add("for-parallel", frag("var @uniform u_k : float4[3]\nvar @uniform u_n : int", "    var s = float4(0.0)\n    for (i, k in range(u_n), u_k) {\n        s += k * float(i)\n    }\n    for (i, j in range(2, 5), range(10, 20)) {\n        s.x += float(i * j)\n    }\n    f_color = s"));
}

/// [`NEEDLES`] of the rows in `functions_and_data`.
const NEEDLES_FUNCTIONS_AND_DATA: &[(&str, Target, &str, &str, bool)] = &[
    ("reference-parameters", Target::Glsl330, ".330.frag", "void bump(inout float x", true),
    ("reference-parameters", Target::Wgsl, ".wgsl", "ptr<function, f32>", true),
    ("var-struct-parameters", Target::Glsl330, ".330.frag", "void unit(inout L l", true),
    ("overloads", Target::Glsl330, ".330.frag", "float luma_float3_(vec3 c)", true),
    ("overloads", Target::Wgsl, ".wgsl", "fn luma_float4_(", true),
    ("default-parameters", Target::Glsl330, ".330.frag", "tone(0.5, 2.0, vec3(0.1))", true),
    ("named-arguments", Target::Glsl330, ".330.frag", "tone_float_float_float3_(0.5, 2.0, vec3(0.1))", true),
    ("named-arguments", Target::Wgsl, ".wgsl", "tone_float_float_float3_(1f, 2f, vec3(0f))", true),
    ("enums", Target::Wgsl, ".wgsl", "i32", true),
];

/// The rows of docs/features.md's "daslang's math module, modules and
/// types" section.
fn snippets_language_l() -> Vec<(&'static str, String)> {
    vec![
        ("matrix-from-matrix", frag("var @uniform u_m : float4x4", "    let n = float3x3(u_m)\n    let a = float4x4(n)\n    let b = float2x3(u_m)\n    let c = float4x2(float2x2(n))\n    f_color = a * float4(n * b[0], 1.0) + c[3].xyxy + (-u_m)[2]")),
        ("math-module", frag("require math\nvar @uniform u_x : float3\nvar @uniform u_i : int2", "    let a = mad(u_x, 2.0, u_x) + mad(u_x, u_x, u_x) + fast_normalize(u_x) + float3(mad(u_i.x, 2, 1))\n    let b = length_sq(u_x) + distance_sq(u_x, a) + inv_length(u_x) + inv_length_sq(u_x) + inv_distance(u_x, a) + inv_distance_sq(u_x, a)\n    let c = rcp_est(b) + rsqrt_est(b) + atan_est(b) + atan2_est(b, 1.0)\n    let d = floori(u_x) + ceili(u_x) + roundi(u_x) + trunci(u_x) + float_bits_to_int(u_x)\n    let e = int_bits_to_float(d) + uint_bits_to_float(float_bits_to_uint(u_x))\n    let m = identity3x3() * a + (identity4x4() * float4(e, 1.0)).xyz\n    f_color = float4(m + float3(c + PI + FLT_EPSILON + FLT_MAX * 0.0 + float(INT_MAX) * 0.0), float(UINT_MAX & uint(INT_MIN + 1)))")),
        ("sincos", frag("var @uniform u_a : float", "    var s, c : float\n    sincos(u_a, s, c)\n    f_color = float4(s, c, 0.0, 1.0)")),
        ("noise-hash", frag("var @uniform u_seed : uint\nvar @uniform u_p : int3", "    let a = uint32_hash(u_seed) ^ uint_noise_1D(u_p.x, u_seed) ^ uint_noise_2D(u_p.xy, u_seed) ^ uint_noise_3D(u_p, u_seed)\n    f_color = float4(float(a >> 8u) / 16777216.0)")),
        ("daslang-host-math", frag("var @uniform u_q : float4", "    f_color = float4(quat_mul_vec(u_q, float3(1.0)), 1.0)")),
        ("pack-unpack", frag("var @uniform u_v : float4\nvar @uniform u_u : uint", "    let a = packUnorm4x8(u_v) ^ packSnorm4x8(u_v) ^ packUnorm2x16(u_v.xy) ^ packSnorm2x16(u_v.zw) ^ packHalf2x16(u_v.xy)\n    f_color = unpackUnorm4x8(a) + unpackSnorm4x8(u_u) + float4(unpackUnorm2x16(u_u), unpackSnorm2x16(a)) + float4(unpackHalf2x16(u_u), 0.0, 0.0)")),
        ("vector-shift-scalar", frag("var @uniform u_v : int3\nvar @uniform u_n : uint", "    let a = u_v << 2\n    var b = uint4(u_n) >> u_n\n    b <<= 1u\n    f_color = float4(float3(a), float(b.x))")),
        ("texture2D", frag("var @uniform t : sampler2D\nvar @uniform c : samplerCube", "    f_color = texture2D(t, float2(0.5)) + texture2DLod(t, float2(0.5), 1.0) + textureCube(c, float3(1.0))")),
        ("constant-builtin-calls", frag("let SUN : float3 = normalize(float3(0.45, 0.55, 0.85))\nlet K = cos(radians(30.0)) * PI\nlet M = float3x3(identity4x4())\nlet N = uint_noise_2D(int2(3, 4), 7u) >> 16u", "    f_color = float4(M * SUN * K, float(N))")),
        ("constant-undefined-call", frag("let K = sqrt(-1.0)", "    f_color = float4(K)")),
        ("require-modules", "require math\nrequire glfw/glfw_boost\nrequire shaders/features/include/shaderlib/tonemap\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(tonemap::aces(palette_ramp(0.5)) * math::saturate(2.0), 1.0)\n}\n".to_string()),
        ("daslang-builtin-modules", "options gen2\nrequire daslib/shader_lingua_franca public\nrequire ./tests/bad_inputs/include/daslang/daslib/shader_lingua_franca.das\nrequire glsl/glsl_common\nvar @uniform t : sampler2D\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = texture(t, float2(0.5)) + float4(fwidth(gl_FragCoord.x))\n}\n".to_string()),
        ("daslang-builtin-unsupported", "require ./tests/bad_inputs/include/daslang/daslib/shader_lingua_franca.das\nvar @out f_color : float4\n[fragment_program]\ndef fs {\n    f_color = float4(float(dot_of_bytes(1u, 2u)))\n}\n".to_string()),
        ("half", frag("let K = 0.5h\ndef tone(c : half3) : half3 {\n    return c / (c + half3(K)) + sin(c) * 0.25h\n}\nvar @uniform u_x : float3", "    let h = tone(half3(u_x)) * half(2) + max(half3(float16(1.0)), half3(0.0h))\n    f_color = float4(float3(h), float(length(h)))")),
        ("half-interface", frag("var @uniform u_h : half", "    f_color = float4(float(u_h))")),
        ("small-integers", frag("", "    let b = byte2(1, 2)\n    f_color = float4(1.0)")),
        ("wide-integers-double", frag("", "    var x : int64\n    var d : double\n    f_color = float4(1.0)")),
    ]
}

/// dasSpirv's builtins and specialization constants (issue 36): in the
/// table with the `glsl430` and `gles310` columns.
fn dasspirv_builtins(add: &mut impl FnMut(&'static str, String)) {
    let buf = "struct Buf {\n    data : float[]\n}\nvar @ssbo b : Buf\n";
    add("subgroups", format!("{buf}[compute_program(local_size_x = 64)]\ndef cs {{\n    let i = gl_GlobalInvocationID.x\n    let v = b.data[i]\n    var r = subgroupAdd(v) + subgroupMul(v) + subgroupMin(v) + subgroupMax(v) + subgroupInclusiveAdd(v) + subgroupExclusiveMul(v)\n    r += subgroupBroadcastFirst(v) + subgroupBroadcast(v, 1u) + subgroupShuffle(v, gl_SubgroupInvocationID ^ 1u) + subgroupShuffleXor(v, 2u) + subgroupShuffleUp(v, 1u) + subgroupShuffleDown(v, 1u)\n    let bits = subgroupAnd(uint(v)) | subgroupOr(1u) ^ uint(subgroupXor(int2(2)).x)\n    let ballot = subgroupBallot(v > 0.0)\n    if (subgroupElect() && subgroupAll(v >= 0.0) || subgroupAny(v < 0.0)) {{\n        r += float(bits + ballot.x + gl_SubgroupSize + gl_NumSubgroups + gl_SubgroupID)\n    }}\n    b.data[i] = r\n}}\n"));
    add("subgroups-fragment", frag("", "    f_color = float4(subgroupAdd(gl_FragCoord.x), float(gl_SubgroupSize), float(gl_SubgroupInvocationID), 1.0)"));
    add("subgroups-vertex", vert("", "    let k = subgroupAdd(1.0)"));
    add("subgroup-clustered", format!("{buf}[compute_program(local_size_x = 64)]\ndef cs {{\n    b.data[0] = subgroupClusteredAdd(b.data[0], 4u)\n}}\n"));
    add("draw-id", vert("var @inout v_k : float", "    v_k = float(gl_DrawID)"));
    add("primitive-id", frag("", "    f_color = float4(float(gl_PrimitiveID), 0.0, 0.0, 1.0)"));
    add("nonuniform-ext", frag("var @uniform u_k : float4[4]\nvar @uniform u_i : int", "    f_color = u_k[nonuniformEXT(u_i) & 3]"));
    add("float-atomics", format!("{buf}[compute_program(local_size_x = 64)]\ndef cs {{\n    atomicAdd(b.data[0], 1.0)\n}}\n"));
    add("specialization-constants", frag("var @constant_id = 0 STEPS : uint = 4\nvar @constant_id = 1 GAIN : float = 0.5\nvar @constant_id = 2 INVERT : bool = false\nvar @constant_id = 7 BIAS : int = -1", "    var s = 0.0\n    for (i in range(int(STEPS))) {\n        s += GAIN\n    }\n    s += float(BIAS)\n    f_color = float4(INVERT ? 1.0 - s : s)"));
    add("specialization-constant-sized-array", frag("var @constant_id = 0 N : int = 4", "    var a : float[N]\n    f_color = float4(a[0])"));
}

/// Extra properties of some outputs: (snippet, target, file suffix, text
/// that must or must not appear).
const NEEDLES: &[(&str, Target, &str, &str, bool)] = &[
    ("subgroups", Target::Wgsl, ".wgsl", "enable subgroups;\ndiagnostic(off, subgroup_uniformity);", true),
    ("subgroups", Target::Glsl430, ".430.comp", "#extension GL_KHR_shader_subgroup_arithmetic : require", true),
    ("subgroups", Target::Glsl430, ".430.comp", "subgroupExclusiveAdd(1u)", true),
    ("primitive-id", Target::Wgsl, ".wgsl", "enable primitive_index;", true),
    ("specialization-constants", Target::Wgsl, ".wgsl", "@id(1) override GAIN: f32 = 0.5f;", true),
    ("specialization-constants", Target::Glsl330, ".330.frag", "const float GAIN = 0.5;", true),
    ("nonuniform-ext", Target::Glsl330, ".330.frag", "u_k[(_e3 & 3)]", true),
    ("ternary-vector-int-bool", Target::Glsl330, ".330.frag", "mix(", false),
    ("ternary-vector-int-bool", Target::Gles300, ".300es.frag", "mix(", false),
    ("ternary-vector-float", Target::Glsl330, ".330.frag", "mix(", true),
    ("integer-division-remainder", Target::Glsl330, ".330.frag", "%", false),
    ("sampler-arrays", Target::Glsl330, ".330.frag", "uniform sampler2D layers_2;", true),
    ("sampler-arrays-dynamic", Target::Wgsl, ".wgsl", "switch", true),
    ("sampler-parameters", Target::Glsl330, ".330.frag", "vec4 get_t()", true),
    ("sampler-parameters", Target::Wgsl, ".wgsl", "fn get_t()", true),
    ("texture-in-vertex", Target::Glsl330, ".330.vert", "textureLod(t", true),
    ("inverse", Target::Wgsl, ".wgsl", "fn inverse_4x4_(", true),
    ("inverse", Target::Glsl330, ".330.frag", "inverse(", false),
    ("textureOffset", Target::Glsl330, ".330.frag", "textureOffset(s, vec3(vec2(0.5), 0.5), ivec2(1, 0))", true),
    ("textureOffset", Target::Wgsl, ".wgsl", "vec2<i32>(-1i, 0i)", true),
    ("texelFetchOffset", Target::Wgsl, ".wgsl", "+ vec2<i32>(1i, -1i)", true),
    ("texture-in-vertex", Target::Wgsl, ".wgsl", "textureSampleLevel(t", true),
    ("gl_PointSize", Target::Glsl330, ".330.vert", "gl_PointSize =", true),
    ("gl_PointSize", Target::Wgsl, ".wgsl", "point", false),
    ("gl_PointCoord", Target::Glsl330, ".330.frag", "gl_PointCoord", true),
    ("gl_PointCoord", Target::Wgsl, ".wgsl", "vec2(0.5f)", true),
    ("nonuniform-sampling", Target::Wgsl, ".wgsl", "diagnostic(off, derivative_uniformity);", true),
    ("matrix-dynamic-index", Target::Wgsl, ".wgsl", "var local", true),
    ("programs-per-file", Target::Glsl330, "quad_fs.330.frag", "\nout vec4 f_color;", true),
    ("programs-per-file", Target::Glsl330, "other_fs.330.frag", "\nout vec4 f_other;", true),
    ("uniform-loose", Target::Glsl330, ".330.frag", "uniform mat4x4 u_m;", true),
    ("uniform-loose", Target::Wgsl, ".wgsl", "var<uniform> uniforms: Uniforms;", true),
    ("uniform-scalar-array", Target::Gles300, ".300es.frag", "uniform float u_w[4];", true),
    ("uniform-scalar-array", Target::Wgsl, ".wgsl", "u_w: array<vec4<f32>, 4>,", true),
    ("uniform-bool", Target::Glsl330, ".330.frag", "uniform bool u_b;", true),
    ("uniform-bool", Target::Wgsl, ".wgsl", "u_b: u32,", true),
    ("uniform-float2x2", Target::Glsl330, ".330.frag", "uniform mat3x2 u_n;", true),
    ("uniform-float2x2", Target::Wgsl, ".wgsl", "u_n: array<vec4<f32>, 3>,", true),
    ("module-variables", Target::Glsl330, ".330.frag", "float angle = 0.25;", true),
    ("bind-groups", Target::Wgsl, ".wgsl", "@group(1) @binding(2) ", true),
    ("bind-groups", Target::Wgsl, ".wgsl", "@group(1) @binding(0) ", true),
    ("bind-groups", Target::Wgsl, ".wgsl", "@group(0) @binding(0) ", true),
    ("module-variables", Target::Wgsl, ".wgsl", "var<private> count: i32 = i32();", true),
    ("pack-unpack", Target::Glsl330, ".330.frag", "pack", false),
    ("pack-unpack", Target::Gles300, ".300es.frag", "pack", false),
    ("pack-unpack", Target::Wgsl, ".wgsl", "pack2x16float(", true),
    ("half", Target::Wgsl, ".wgsl", "enable f16;", true),
    ("constant-builtin-calls", Target::Wgsl, ".wgsl", "const SUN: vec3<f32> = vec3<f32>(0.4061643f, 0.49642307f, 0.7671993f);", true),
    ("constant-builtin-calls", Target::Glsl330, ".330.frag", "const vec3 SUN = vec3(0.4061643, 0.49642307, 0.7671993);", true),
    ("texture2D", Target::Glsl330, ".330.frag", "texture2D", false),
];

#[derive(Debug, PartialEq)]
enum Status {
    Yes,
    Lowered,
    No,
}

struct Row {
    id: String,
    cells: Vec<Status>,
}

/// The columns of the matrix; the compute table has the last two too.
const COLUMNS: [Target; 6] = [Target::Glsl330, Target::Gles300, Target::Wgsl, Target::Spirv, Target::Glsl430, Target::Gles310];

fn rows() -> Vec<Row> {
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/features.md")).expect("docs/features.md exists");
    let mut rows = Vec::new();
    for line in doc.lines() {
        // Split on `|`, but not on the escaped `\|` inside cells.
        let masked = line.trim().replace("\\|", "\u{1}");
        let cells: Vec<String> = masked.trim_matches('|').split('|').map(|c| c.trim().replace('\u{1}', "|")).collect();
        if !line.trim_start().starts_with("| `") || cells.len() < 6 {
            continue;
        }
        let id = cells[0].trim_matches('`').to_string();
        let status = |c: &str| match c {
            "yes" => Status::Yes,
            "lowered" => Status::Lowered,
            "no" => Status::No,
            other => panic!("row `{id}`: unknown status `{other}` (yes, lowered, no)"),
        };
        // The compute table: two more status columns (glsl430, gles310).
        let statuses = if cells.len() >= 9 && ["yes", "lowered", "no"].contains(&cells[6].as_str()) { 6 } else { 4 };
        rows.push(Row { id: id.clone(), cells: cells[2..2 + statuses].iter().map(|c| status(c.as_str())).collect() });
    }
    rows
}

#[test]
fn feature_matrix_matches_the_compiler() {
    let snippets = snippets();
    let rows = rows();
    let ids: Vec<&str> = rows.iter().map(|r| r.id.as_str()).collect();
    for id in snippets.keys() {
        assert!(ids.contains(id), "snippet `{id}` has no row in docs/features.md");
    }
    let mut failures = Vec::new();
    for row in &rows {
        let Some(src) = snippets.get(row.id.as_str()) else {
            failures.push(format!("docs/features.md row `{}` has no snippet in tests/compiler/features.rs", row.id));
            continue;
        };
        for (target, status) in COLUMNS.iter().zip(&row.cells) {
            let opts = umbrac::Options { targets: vec![*target], ..Default::default() };
            let c = umbrac::compile_source(&format!("{}.das", row.id), src, &opts);
            let bug = c.diagnostics.iter().any(|d| d.severity == umbrac::Severity::Bug);
            if bug {
                failures.push(format!("`{}` on {}: internal error:\n{}", row.id, target.name(), c.render_diagnostics()));
                continue;
            }
            match (status, &c.result) {
                (Status::No, None) => {}
                (Status::No, Some(_)) => failures.push(format!("`{}` on {}: the matrix says `no`, but it compiles", row.id, target.name())),
                (_, None) => failures.push(format!("`{}` on {}: the matrix says it compiles, but:\n{}", row.id, target.name(), c.render_diagnostics())),
                (_, Some(compiled)) => {
                    let dir = tempfile::tempdir().unwrap();
                    support::write_all(dir.path(), &compiled.artifacts);
                    support::validate_dir(dir.path(), &compiled.reflection);
                    for (id, t, suffix, needle, present) in NEEDLES.iter().chain(NEEDLES_FUNCTIONS_AND_DATA) {
                        if *id != row.id || t != target {
                            continue;
                        }
                        let text: String = compiled.artifacts.iter().filter(|a| a.file_name.ends_with(suffix)).map(|a| a.text().into_owned()).collect();
                        if text.contains(needle) != *present {
                            failures.push(format!("`{id}` on {}: output {} `{needle}`:\n{text}", t.name(), if *present { "lacks" } else { "contains" }));
                        }
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

/// Prints the first error of every `no` row (run with --nocapture when
/// editing the matrix, to see that each fails for the documented reason).
#[test]
fn refusals_say_why() {
    let snippets = snippets();
    for row in rows().iter().filter(|r| r.cells.iter().all(|c| *c == Status::No)) {
        let c = umbrac::compile_source("x.das", &snippets[row.id.as_str()], &Default::default());
        let first = c.diagnostics.iter().find(|d| d.is_error()).map(|d| d.message.clone()).unwrap_or_default();
        eprintln!("{}: {first}", row.id);
        assert!(!first.is_empty(), "`{}` fails without an error", row.id);
    }
}

//! Functions and data as daslang writes them, run on every consumer
//! (`programs::assert_all_hold`): results inferred from `return`, default
//! values, arguments by name, `var` and `var p : T&` parameters (through
//! the temporaries the lowering adds for fields, elements and repeated
//! arguments), overloads, pipes, postfix `if`, `with`, enumerations,
//! construction by field name and `for` over arrays and several sources. Every input depends on `z`
//! or `fz` (zero at run time), so the device computes the values.

use crate::programs::assert_all_hold;

#[test]
fn functions_hold_on_every_consumer() {
    let decls = "\
def half_of(x : float) {
    return x * 0.5
}
def twice(x : int) => x * 2
def third(x : float) -> float {
    return x / 3.0
}
def tone(x : float; gain : float = 2.0; bias : float = 0.25) => x * gain + bias
def shrink(var x : float) : float {
    x *= 0.5
    return x + 1.0
}
def keep(x : float) : float {
    let before = x
    let y = shrink(x)
    return before + y * 0.0
}
def luma(c : float3) => c.g
def luma(c : float4) => c.a
def luma(c : float) => c * 10.0
def sub(a, b : int) => a - b
def sq(x : int) => x * x
def band(x : float) : float {
    return 0.0 if (x < 0.25)
    return 1.0 if (x > 0.75) else return 0.5
}
def count_to(n : int) : int {
    var s = 0
    var i = 0
    while (true) {
        i++
        continue if (i == 2)
        break if (i > n)
        s += i
    }
    return s
}
struct Ray {
    o : float3
    d : float3
}
def Ray(from, to : float3) : Ray {
    return Ray(o = from, d = to - from)
}
";
    assert_all_hold(
        "functions",
        decls,
        &[
            "half_of(3.0 + fz) == 1.5",
            "twice(21 + z) == 42",
            "third(9.0 + fz) == 3.0",
            // Defaults filled in from the right.
            "tone(1.0 + fz) == 2.25 && tone(1.0 + fz, 3.0) == 3.25 && tone(1.0 + fz, 3.0, fz) == 3.0",
            // By name, in any order; a default between the values given.
            "tone([bias = fz, x = 1.0 + fz]) == 2.0 && tone([gain = 3.0, x = 1.0 + fz]) == 3.25",
            // A `var` parameter is the callee's copy.
            "shrink(4.0 + fz) == 3.0 && keep(4.0 + fz) == 4.0",
            // The argument types pick the overload.
            "luma(float3(1.0, 2.0 + fz, 3.0)) == 2.0 && luma(float4(1.0, 2.0, 3.0, 4.0 + fz)) == 4.0 && luma(0.5 + fz) == 5.0",
            // `x |> f(y)` is `f(x, y)`; `f(y) <| x` is `f(y, x)`.
            "((10 + z) |> sub(3)) == 7 && (sub(10 + z) <| 3) == 7 && ((10 + z) |> sub(3) |> sub(2)) == 5",
            // Pipes bind tighter than `+`: `2 + (z |> sq())`.
            "(2 + z |> sq()) == 2",
            "band(0.1 + fz) == 0.0 && band(0.5 + fz) == 0.5 && band(0.9 + fz) == 1.0",
            "count_to(5 + z) == 13",
            // A function named like its struct is its initializer.
            "Ray(float3(1.0 + fz), float3(3.0)).d == float3(2.0) && Ray(o = float3(fz), d = float3(1.0)).o == float3(0.0)",
        ],
    );
}

#[test]
fn reference_parameters_hold_on_every_consumer() {
    let decls = "\
struct S {
    v : float3
    n : int
}
def bump(var x : float&; by : float) {
    x += by
}
def bump_twice(var x : float&; by : float) {
    bump(x, by)
    bump(x, by)
}
def grow(var s : S&) {
    s.v *= 2.0
    s.n += 1
    bump(s.v.y, 0.5)
}
// A `var` struct or array parameter is the caller's variable (daslang
// passes structs and arrays by reference), or a copy of a value.
def reset(var s : S) {
    s.n = 7
    s.v.z = -1.0
}
def fill(var a : int[3]; k : int) {
    for (i in range(3)) {
        a[i] = k + i
    }
}
def var_struct(z : int) : int {
    var s = S(float3(1.0), z)
    reset(s)
    let t = S(float3(2.0), 3 + z)
    reset(t)
    var arr : int[3]
    fill(arr, 10 + z)
    return s.n * 1000 + int(s.v.z) * 100 + t.n * 10 + arr[2] - 12
}
def swap(var a, b : int&) {
    let t = a
    a = b
    b = t
}
def set_both(var a : int&; var b : int&) {
    a = 1
    b = 2
}
def local_var(z : float) : float {
    var a = 1.0 + z
    bump_twice(a, 0.25)
    return a
}
def field(z : int) : float3 {
    var s = S(float3(1.0), z)
    grow(s)
    grow(s)
    return s.v + float3(float(s.n))
}
def element(z : int) : float {
    var arr : float[3]
    for (i in range(3)) {
        bump(arr[(i + 1 + z) % 3], float(i))
    }
    return arr[0] * 100.0 + arr[1] * 10.0 + arr[2]
}
def swapped(z : int) : int {
    var a = 3 + z
    var b = 4
    swap(a, b)
    return a * 10 + b
}
def repeated(z : int) : int {
    var a = z
    set_both(a, a)
    return a
}
def twist(var p : float2&) {
    p = p.yx
}
def swizzled(z : float) : float4 {
    var c = float4(1.0, 2.0, 3.0, 4.0 + z)
    twist(c.wy)
    return c
}
def component(z : float) : float4 {
    var c = float4(z)
    bump(c.z, 2.0)
    bump(c.x, 1.0)
    return c
}
";
    assert_all_hold(
        "reference_parameters",
        decls,
        &[
            "local_var(fz) == 1.5",
            // Fields through a struct reference, and a reference passed on.
            "field(z) == float3(6.0, 7.5, 6.0)",
            // Elements picked at run time: through a temporary, written back.
            "element(z) == 201.0",
            "swapped(z) == 43",
            "var_struct(z) == 7000 - 100 + 30",
            // Two references to one variable: written back in order, the last wins.
            "repeated(z) == 2",
            "component(fz) == float4(1.0, 0.0, 2.0, 0.0)",
            // Two components of a vector: the others keep their values.
            "swizzled(fz) == float4(1.0, 4.0, 3.0, 2.0)",
        ],
    );
}

#[test]
fn enumerations_and_constructions_hold_on_every_consumer() {
    let decls = "\
enum Mode {
    flat
    lit = 4
    toon
}
enum Bits : uint {
    a = 1
    b
}
enum Small : uint8 {
    top = 255
    wrapped
}
let W = fixed_array<int>(10, 11, 12, 13, 14, 15)
def pick(m : Mode) : int {
    return W[m]
}
def mode_of(z : int) => z == 0 ? Mode.toon : Mode.flat
struct M {
    albedo : float3 = float3(0.5)
    rough = 0.25
    metal : float
    id : int
}
struct Light {
    dir : float3
    k : float
}
def hidden(k : float) : float {
    var l = Light(dir = float3(1.0), k = 5.0)
    var s = 0.0
    with (l) {
        // The field hides the parameter.
        s = k
    }
    let dir = float3(10.0)
    with (l) {
        // A local hides the field.
        s += dir.x
    }
    return s
}
def lit(z : float) : float {
    var l = Light(dir = float3(1.0, 2.0, 3.0 + z), k = 2.0)
    with (l) {
        k += 1.0
        dir.x = k
    }
    var s = 0.0
    with (l) {
        let k = 100.0
        s = dir.x + dir.z + k
    }
    return s + l.k
}
";
    assert_all_hold(
        "enumerations_and_constructions",
        decls,
        &[
            "int(Mode.flat) + z == 0 && int(Mode.lit) == 4 && int(Mode.toon) + z == 5",
            "mode_of(z) == Mode.toon && mode_of(z + 1) != Mode.toon && mode_of(z) > Mode.lit && Mode.flat < mode_of(z)",
            "pick(mode_of(z)) == 15 && W[Mode.lit] + z == 14",
            "uint(Bits.b) + uz == 2u && uint(Small.wrapped) + uz == 0u",
            // Fields left out take their initial values, or zero.
            "M().albedo == float3(0.5) && M().rough + fz == 0.25 && M().metal + fz == 0.0 && M().id + z == 0",
            "M(metal = 1.0 + fz, id = 3).rough == 0.25 && M(metal = 1.0 + fz, id = 3).metal == 1.0 && M(rough = fz).albedo == float3(0.5)",
            // `with`: fields read and written in place; a local declared inside hides one.
            "lit(fz) == 3.0 + 3.0 + 100.0 + 3.0",
            "hidden(fz) == 15.0",
        ],
    );
}

#[test]
fn for_over_arrays_holds_on_every_consumer() {
    let decls = "\
def sum(z : int) : int {
    let arr = fixed_array<int>(1, 2, 3, 4)
    var s = z
    for (x in arr) {
        s += x
    }
    return s
}
def fill(z : int) : int {
    var arr : int[4]
    for (x in arr) {
        x = 7 + z
    }
    var i = 0
    for (x in arr) {
        x += i
        i++
    }
    return arr[0] * 1000 + arr[1] * 100 + arr[2] * 10 + arr[3]
}
def weighted(n : int) : int {
    let arr = fixed_array<int>(5, 6, 7)
    var s = 0
    for (i, x in range(n), arr) {
        s += i * x
    }
    return s
}
def shifted(z : int) : int {
    let arr = fixed_array<int>(1, 10, 100, 1000)
    var s = 0
    for (i, x in range(-2 + z, 100), arr) {
        s += i * x
    }
    return s
}
def three(z : int) : int {
    let arr = fixed_array<int>(1, 2, 3, 4, 5)
    var s = 0
    var steps = 0
    for (i, j, k in range(3 + z, 10), range(20u, 23u), arr) {
        s += i * int(j) * k
        steps++
    }
    return s * 10 + steps
}
def pairs(z : int) : int {
    let a = fixed_array<int>(1, 2, 3)
    let b = fixed_array<int>(10, 20)
    var s = z
    for (x, y in a, b) {
        s += x * y
    }
    return s
}
def broken(z : int) : int {
    let arr = fixed_array<int>(1, 2, 3, 4)
    var s = 0
    for (x in arr) {
        continue if (x == 2 + z)
        break if (x == 4)
        s += x
    }
    return s
}
";
    assert_all_hold(
        "for_over_arrays",
        decls,
        &[
            "sum(z) == 10",
            "fill(z) == 7900",
            // The shortest source ends the loop: a range shorter than the
            // array, and longer.
            "weighted(2 + z) == 6 && weighted(10 + z) == 20",
            "shifted(z) == -2 + -10 + 0 + 1000",
            "three(z) == (3 * 20 * 1 + 4 * 21 * 2 + 5 * 22 * 3) * 10 + 3",
            "pairs(z) == 50",
            "broken(z) == 4",
        ],
    );
}

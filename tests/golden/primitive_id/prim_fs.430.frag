#version 430 core
struct prim_fs_out {
    vec4 f_color;
};
out vec4 f_color;

void main() {
    uint PrimitiveID = uint(gl_PrimitiveID);
    vec4 out_f_color = vec4(0.0);
    int _e1 = int(PrimitiveID);
    int k = (_e1 - (8 * (_e1 / 8)));
    out_f_color = vec4((float(k) / 7.0), float((_e1 & 1)), 0.0, 1.0);
    vec4 _e16 = out_f_color;
    prim_fs_out _tmp_return = prim_fs_out(_e16);
    f_color = _tmp_return.f_color;
    return;
}


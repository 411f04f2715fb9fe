"""GLSL 3.30 core programs of the 3-D view.

PATH: one vertex per segment end (float32 position, uint8 group normalised to 0..1);
the line strip's segment takes its last vertex's flat colour, and a segment whose
end vertex index is at most ``u_done`` is drawn finished: the progress of a job is
one uniform. MEASURED: rows x, y, z, deviation (< 0 during rapids: grey); the colour ramp is a uniform (the
same three colours as ``measured.RAMP``). LINES: position and colour per vertex.
"""

PATH_VERTEX = """
#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in float a_group;
uniform mat4 u_mvp;
uniform int u_done;
uniform vec4 u_colours[8];
uniform vec4 u_done_colour;
flat out vec4 v_colour;
void main() {
    gl_Position = u_mvp * vec4(a_pos, 1.0);
    int group = int(a_group * 255.0 + 0.5);
    v_colour = (gl_VertexID <= u_done && group != 0) ? u_done_colour : u_colours[group];
}
"""

FLAT_FRAGMENT = """
#version 330 core
flat in vec4 v_colour;
out vec4 colour;
void main() { colour = v_colour; }
"""

MEASURED_VERTEX = """
#version 330 core
layout(location = 0) in vec4 a_row;
uniform mat4 u_mvp;
uniform float u_tolerance;
uniform vec3 u_ramp[3];
out vec4 v_colour;
void main() {
    gl_Position = u_mvp * vec4(a_row.xyz, 1.0);
    float t = clamp(a_row.w / u_tolerance, 0.0, 1.0) * 2.0;
    vec3 rgb = u_ramp[0] + (u_ramp[1] - u_ramp[0]) * min(t, 1.0)
             + (u_ramp[2] - u_ramp[1]) * max(t - 1.0, 0.0);
    v_colour = a_row.w < 0.0 ? vec4(0.6, 0.6, 0.6, 0.6) : vec4(rgb, 1.0);  // rapids: no deviation
}
"""

SMOOTH_FRAGMENT = """
#version 330 core
in vec4 v_colour;
out vec4 colour;
void main() { colour = v_colour; }
"""

LINES_VERTEX = """
#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_rgb;
uniform mat4 u_mvp;
out vec4 v_colour;
void main() {
    gl_Position = u_mvp * vec4(a_pos, 1.0);
    v_colour = vec4(a_rgb, 1.0);
}
"""

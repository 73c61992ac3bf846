#!/usr/bin/env python3
"""Draws docs/pressure-angle.svg: the pressure angle of an oscillating roller follower, at the
roller's centre (the textbook's), beside the contact point's direction of motion (not it).

Plain geometry, no camkin: an eccentric disc, an arm about a pivot, the roller touching the disc.
Run: python3 scripts/figures/pressure-angle.py > docs/pressure-angle.svg"""
import math

A = (0.0, 0.0)  # the disc's centre (the cam, turned to some angle)
R = 30.0  # the disc's radius
r = 14.0  # the roller's radius
PHI_C = math.radians(150.0)  # where the roller's centre is, seen from the disc's centre
PSI = math.radians(-95.0)  # the arm's direction, from the roller's centre to the pivot
L = 46.0  # the arm's length to the roller's centre


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def add(p, q):
    return (p[0] + q[0], p[1] + q[1])


def mul(k, p):
    return (k * p[0], k * p[1])


def norm(p):
    return math.hypot(*p)


def unit(p):
    return mul(1 / norm(p), p)


def rot90(p):
    return (-p[1], p[0])


C = add(A, mul(R + r, (math.cos(PHI_C), math.sin(PHI_C))))  # the roller's centre
O = add(C, mul(L, (math.cos(PSI), math.sin(PSI))))  # the arm's pivot
P = add(A, mul(R, unit(sub(C, A))))  # the contact point
force = unit(sub(C, A))  # the force line, from the cam through the contact and the centre
v_c = unit(rot90(sub(C, O)))  # the centre's direction of motion
v_p = unit(rot90(sub(P, O)))  # the contact point's
if v_c[0] * force[0] + v_c[1] * force[1] < 0:
    v_c, v_p = mul(-1, v_c), mul(-1, v_p)
alpha = math.degrees(math.atan2(v_c[0] * force[1] - v_c[1] * force[0], v_c[0] * force[0] + v_c[1] * force[1]))
wrong = math.degrees(math.atan2(v_p[0] * force[1] - v_p[1] * force[0], v_p[0] * force[0] + v_p[1] * force[1]))

S, X0, Y0 = 4.6, 545.0, 330.0


def px(p):
    return (X0 + S * p[0], Y0 - S * p[1])


def line(p, q, style):
    (x1, y1), (x2, y2) = px(p), px(q)
    return f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" {style}/>'


def arrow(p, q, style, marker):
    return line(p, q, style + f' marker-end="url(#{marker})"')


def text(p, s, dx=0, dy=0, anchor="start", extra=""):
    x, y = px(p)
    return f'<text x="{x + dx:.1f}" y="{y + dy:.1f}" text-anchor="{anchor}" {extra}>{s}</text>'


def circle(c, rad, style):
    x, y = px(c)
    return f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{S * rad:.1f}" {style}/>'


def arc(c, rad, a0, a1, style):
    # from direction a0 to a1 (degrees, counter-clockwise in the world)
    p0 = px(add(c, mul(rad, (math.cos(math.radians(a0)), math.sin(math.radians(a0))))))
    p1 = px(add(c, mul(rad, (math.cos(math.radians(a1)), math.sin(math.radians(a1))))))
    sweep = 0 if a1 > a0 else 1
    return f'<path d="M {p0[0]:.1f} {p0[1]:.1f} A {S * rad:.1f} {S * rad:.1f} 0 0 {sweep} {p1[0]:.1f} {p1[1]:.1f}" {style}/>'


ang = lambda v: math.degrees(math.atan2(v[1], v[0]))
out = [
    '<svg xmlns="http://www.w3.org/2000/svg" width="720" height="520" viewBox="0 0 720 520" font-family="DejaVu Sans, sans-serif" font-size="15">',
    '<defs>',
    '<marker id="red" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="8" markerHeight="8" orient="auto-start-reverse"><path d="M0 0 L10 5 L0 10 z" fill="#c0392b"/></marker>',
    '<marker id="blue" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="8" markerHeight="8" orient="auto-start-reverse"><path d="M0 0 L10 5 L0 10 z" fill="#1f5fa8"/></marker>',
    '<marker id="grey" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="8" markerHeight="8" orient="auto-start-reverse"><path d="M0 0 L10 5 L0 10 z" fill="#888"/></marker>',
    '</defs>',
    '<rect width="720" height="520" fill="white"/>',
    circle(A, R, 'fill="#e8e8e8" stroke="#333" stroke-width="2"'),
    text(A, "cam", anchor="middle", dy=5),
    line(O, C, 'stroke="#333" stroke-width="6" stroke-linecap="round"'),
    circle(O, 1.2, 'fill="#333"'),
    text(O, "pivot O", dx=-12, dy=5, anchor="end"),
    circle(C, r, 'fill="#f6f0d8" stroke="#333" stroke-width="2"'),
    circle(C, 0.9, 'fill="#333"'),
    text(C, "roller centre C", dx=-14, dy=26, anchor="end"),
    circle(P, 0.9, 'fill="#333"'),
    text(P, "contact P", dx=10, dy=16),
    # the force line through P and C
    line(add(A, mul(R - 12, force)), add(C, mul(28, force)), 'stroke="#c0392b" stroke-width="2" stroke-dasharray="8 5"'),
    arrow(C, add(C, mul(36, force)), 'stroke="#c0392b" stroke-width="2.5"', "red"),
    text(add(C, mul(36, force)), "force line (common normal)", dx=-4, dy=22, anchor="end", extra='fill="#c0392b"'),
    # the centre's direction of motion
    arrow(C, add(C, mul(36, v_c)), 'stroke="#1f5fa8" stroke-width="2.5"', "blue"),
    text(add(C, mul(36, v_c)), "C’s motion (⊥ OC)", dx=-8, dy=-10, anchor="end", extra='fill="#1f5fa8"'),
    arc(C, 22, ang(v_c), ang(force), 'fill="none" stroke="#333" stroke-width="1.5"'),
    text(add(C, mul(24, unit(add(v_c, force)))), f"α = {alpha:.1f}°", dx=-6, anchor="end", extra='font-weight="bold"'),
    # the contact point's direction of motion: not the pressure angle
    arrow(P, add(P, mul(30, v_p)), 'stroke="#888" stroke-width="2" stroke-dasharray="4 3"', "grey"),
    f'<text x="20" y="490" fill="#666" font-size="13">grey, dashed: the contact point’s direction of motion, {wrong:.1f}° from the force line: not the pressure angle</text>',
    f'<text x="20" y="30" font-size="17" font-weight="bold">Pressure angle of an oscillating roller follower</text>',
    f'<text x="20" y="52" font-size="14">from the direction of motion of the roller\'s centre to the line of the contact force</text>',
    "</svg>",
]
print("\n".join(out))

"""The general contact API against closed forms and finite differences of positions (which share
no formula with the method)."""

import math
import pickle

import numpy as np
import pytest

import camkin


def test_two_discs_closed_forms():
    ra, rb, wa, wb = 2.0, 1.0, 3.0, -5.0
    a = camkin.Body(angular_velocity=wa)
    b = camkin.Body(position=(ra + rb, 0.0), angular_velocity=wb)
    c = camkin.contact(camkin.Circle((0, 0), ra), a, camkin.Circle((0, 0), rb), b)
    assert c.touching and abs(c.gap) < 1e-12
    assert np.allclose(c.point_a, [ra, 0.0], atol=1e-12)
    # two counter-clockwise circles touching externally
    assert c.sigma == -1.0
    # the contact point stays at (ra, 0); relative to each body it runs back along the circle
    assert c.sliding_rate_a == pytest.approx(-wa * ra, rel=1e-12)
    assert c.sliding_rate_b == pytest.approx(-wb * rb, rel=1e-12)
    assert c.kappa_a == pytest.approx(1 / ra) and c.kappa_b == pytest.approx(1 / rb)


def ellipse_support(a, b, theta):
    """How far above its centre a centred ellipse turned by theta reaches (the flat face's
    position): the support function, from the geometry alone."""
    return math.sqrt((a * math.sin(theta)) ** 2 + (b * math.cos(theta)) ** 2)


@pytest.mark.parametrize("theta", [0.3, 1.1, 2.0, 4.0])
def test_constraint_row_gives_the_flat_faces_acceleration_by_finite_differences(theta):
    a, b, w, al = 3.0, 2.0, 7.0, 0.0
    h = ellipse_support(a, b, theta)
    eps = 1e-4
    dh = (ellipse_support(a, b, theta + eps) - ellipse_support(a, b, theta - eps)) / (2 * eps)
    d2h = (
        ellipse_support(a, b, theta + eps) - 2 * h + ellipse_support(a, b, theta - eps)
    ) / eps**2
    cam = camkin.Body(angle=theta, angular_velocity=w, angular_acceleration=al)
    face = camkin.Body(position=(0.0, h), velocity=(0.0, w * dh))
    c = camkin.contact(camkin.Ellipse((0, 0), (a, b)), cam, camkin.Line((0, 0), (1, 0)), face)
    assert c.touching
    # phi_q · q̈ = gamma with the cam's q̈ = (0, 0, α) and the face's (0, ÿ, 0): solve for ÿ
    ydd = (c.gamma - c.phi_q[2] * al) / c.phi_q[4]
    assert ydd == pytest.approx(w * w * d2h, rel=1e-6)
    # the residual with that acceleration is zero; with another it is not
    moving = camkin.Body(position=(0.0, h), velocity=(0.0, w * dh), acceleration=(0.0, ydd))
    c2 = camkin.contact(camkin.Ellipse((0, 0), (a, b)), cam, camkin.Line((0, 0), (1, 0)), moving)
    assert abs(c2.acceleration_residual) < 1e-9 * w * w * a
    # the normal velocity vanishes at a contact that is kept (to the finite difference's error)
    assert abs(c.normal_velocity) < 1e-6 * w * a


def test_spline_pair_by_guess_and_at():
    # a spline through points of a circle of radius 2, and a disc of radius 1 beside it
    t = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    sp = camkin.Spline(np.c_[2 * np.cos(t), 2 * np.sin(t)], parameterization="chord-length")
    a = camkin.Body(angular_velocity=1.0)
    b = camkin.Body(position=(3.5, 0.0))
    c = camkin.contact(sp, a, camkin.Circle((0, 0), 1.0), b)
    assert c.status == "apart" and c.gap > 0 and c.phi_q is None
    again = camkin.contact(sp, a, camkin.Circle((0, 0), 1.0), b, guess=(c.u_a, c.u_b))
    assert again.u_a == pytest.approx(c.u_a, abs=1e-12) and again.gap == pytest.approx(c.gap)
    given = camkin.contact(sp, a, camkin.Circle((0, 0), 1.0), b, at=(c.u_a, c.u_b))
    assert given.phi_q is not None and given.phi_q.shape == (6,)
    deep = camkin.contact(sp, a, camkin.Circle((0, 0), 1.0), camkin.Body(position=(2.5, 0.0)))
    assert deep.status == "overlapping" and deep.gap < 0


def test_knife_edge_point():
    # a point at (0, 2) above a disc of radius 2 turning: the point touches at the top
    c = camkin.contact(camkin.Circle((0, 0), 2.0), camkin.Body(angular_velocity=2.0), camkin.Point((0, 0)), camkin.Body(position=(0, 2)))
    assert c.touching and c.sliding_rate_b == 0.0
    assert c.sliding_rate_a == pytest.approx(-2.0 * 2.0, rel=1e-12)


def test_curves_bodies_contacts_pickle_and_are_immutable():
    objs = [
        camkin.Spline([[1, 0], [0, 1], [-1, 0], [0, -1]]),
        camkin.Circle((1, 2), 3.0),
        camkin.Ellipse((0, 0), (2, 1), 30.0),
        camkin.Line((0, 0), (0, 1)),
        camkin.Point((1, 1)),
    ]
    for c in objs:
        c2 = pickle.loads(pickle.dumps(c))
        assert repr(c2) == repr(c)
        e1, e2 = c.eval(0.3), c2.eval(0.3)
        assert all(np.array_equal(e1[k], e2[k], equal_nan=True) for k in e1)
        with pytest.raises(AttributeError):
            c.kind = "x"
    b = camkin.Body(position=(1, 2), angle=0.5, velocity=(3, 4), angular_velocity=5, acceleration=(6, 7), angular_acceleration=8)
    b2 = pickle.loads(pickle.dumps(b))
    assert repr(b2) == repr(b)
    with pytest.raises(AttributeError):
        b.angle = 1.0
    con = camkin.contact(camkin.Circle((0, 0), 2.0), camkin.Body(), camkin.Circle((0, 0), 1.0), camkin.Body(position=(3, 0)))
    con2 = pickle.loads(pickle.dumps(con))
    assert con2.gamma == con.gamma and np.array_equal(con2.phi_q, con.phi_q)
    with pytest.raises(Exception):
        con.gap = 1.0


def test_curve_eval_against_the_circle():
    c = camkin.Circle((1.0, 0.0), 2.0)
    e = c.eval(0.5)
    assert np.allclose(e["r"], [1 + 2 * math.cos(0.5), 2 * math.sin(0.5)], atol=1e-15)
    assert e["curvature"] == pytest.approx(0.5)
    assert c.domain == ("periodic", 0.0, pytest.approx(2 * math.pi))


def test_curves_take_what_a_mechanism_file_takes():
    # issue 44: collinear points fold the spline (the file refuses them; Python took them), and a
    # semi-axis of 1e-300 is below the sizes the computation keeps (every row failed later)
    with pytest.raises(camkin.InputError) as e:
        camkin.Spline([[0, 0], [1, 0], [2, 0], [3, 0]])
    assert e.value.field == "points" and "collinear" in str(e.value)
    with pytest.raises(camkin.InputError) as e:
        camkin.Spline([[0, 0], [2, 2], [2, 0], [0, 2], [-1, 1]])
    assert e.value.field == "points" and "crosses itself" in str(e.value)
    with pytest.raises(camkin.InputError) as e:
        camkin.Ellipse((0, 0), (1e-300, 1))
    assert e.value.field == "semi_axes[0]" and "1e-100" in str(e.value)
    with pytest.raises(camkin.InputError) as e:
        camkin.Circle((0, 0), 1e101)
    assert e.value.field == "radius"
    # at the edges of the range they are taken
    camkin.Circle((0, 0), 1e-100)
    camkin.Ellipse((0, 0), (1e100, 1.0))

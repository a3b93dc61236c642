"""derivations.charbonnier1908.truth: the integrated models against closed forms."""
import mpmath as mp

from derivations.charbonnier1908 import truth


def test_the_sine_swing_lasts_the_exact_half_period():
    sw = truth.swing("sine", "0.3", "1.3", 20)
    with mp.workdps(20):
        exact = 2 * mp.ellipk(mp.sin(mp.mpf("0.15")) ** 2) / mp.mpf("1.3")
        assert abs(sw.T - exact) < mp.mpf("1e-15")
        assert abs(sw.amp - mp.mpf("0.3")) < mp.mpf("1e-15")     # the conservative swing returns to α


def test_the_linear_oscillator_swing():
    # θ'' + k²θ + εθ = 0 swings in π/√(k² + ε)
    sw = truth.oscillator("theta^1", "0.01", "1.7", "-0.4", "0", 20)
    with mp.workdps(20):
        assert abs(sw.T - mp.pi / mp.sqrt(mp.mpf("1.7") ** 2 + mp.mpf("0.01"))) < mp.mpf("1e-15")


def test_every_law_has_its_model_text():
    assert set(truth.LAWS) == set(truth.MODEL_TEXT)

#!/usr/bin/python3
"""Prints the polynomial of src/srgb_avx512.cpp: 255 * 1.055 * m^(5/12) for m in [0.75, 1.5]
as coefficients of (m - 1)^0 .. (m - 1)^6, a least-squares fit on Chebyshev points, each
rounded to float. The test Srgb.SixteenLanesEncodeEveryFloatExactly checks what the encode
makes of it on every float in [0, 1]."""
import numpy as np
from numpy.polynomial import Chebyshev, Polynomial

DEGREE = 6
m = 1.125 + 0.375 * np.cos(np.pi * (np.arange(4001) + 0.5) / 4001)  # Chebyshev points of [0.75, 1.5]
fit = Chebyshev.fit(m - 1.0, 255.0 * 1.055 * m ** (5.0 / 12.0), DEGREE).convert(kind=Polynomial)
coefficients = [float(np.float32(c)) for c in fit.coef]
grid = np.linspace(0.75, 1.5, 200001)
error = np.max(np.abs(Polynomial(coefficients)(grid - 1.0) - 255.0 * 1.055 * grid ** (5.0 / 12.0)))
print('constexpr float kPower[%d] = {%s};' % (DEGREE + 1, ', '.join('%.9gf' % c for c in coefficients)))
print('// largest error on [0.75, 1.5] in double: %.2g (of Y, in steps of the stored value)' % error)

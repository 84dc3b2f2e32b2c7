%
O0012
(plunge grind the top of a block, X 10..90 and Z -4..34, with a 10 mm wide wheel:)
(reversals at X0 and X100, crossover Z0..30; the dress program O12 runs before the cycle)
(and twice during it; then a G91 cycle takes the reversal points, crossover and picks from the first)
G90 G94 G21
G0 X0. Y5. Z0.
G1 Y0.1 F200.
G83.1 X100. Y-0.2 J0.1 Z30. K8. Q0.1 F20. E3000. P12 D2 L1
G0 Y5.
G0 X0. Z0.
G1 Y-0.2 F200.
G91 G83 Y-0.05 J0.02 Q0.01 L2
G90 G0 Y20.
M30

O0002 (the Fanuc twin of tests/oracle/cases/macro_twin_fanuc2.ngc)
G21 G90 G17
#500 = 6 (holes)
#501 = 20 (radius)
G65 P8000 X40 Y40 R#501 K#500
#1 = 0
DO 1
  #1 = #1 + 1
  IF [#1 GT 3] GOTO 20
  G1 X[40 + #1 * 5] Y[40 - #1 * 2] F[100 * #1]
END 1
N20 M98 P8100 L2
G0 X[ROUND[7.5]] Y[FIX[2.5] + 10] Z[FUP[1.2]]
G1 X[SQRT[16] + 7 MOD 3] Y[ATAN[1]/[1]] F200
M98 P8200
G1 X99 (skipped: O8200 returns to N30)
N30 G0 Z5
M30
O8000 (bolt circle: centre X Y, radius R, K holes)
#10 = 0
WHILE [#10 LT #6] DO 1
  #11 = 360 / #6 * #10
  G0 X[#24 + #18 * COS[#11]] Y[#25 + #18 * SIN[#11]]
  G1 Z-1 F120
  G0 Z1
  #10 = #10 + 1
END 1
G0 X[#24 + #18] Y#25
G2 X[#24 - #18] Y#25 I[-#18] J0 F300
G2 X[#24 + #18] Y#25 I#18 J0
M99
O8100 (a nested call, run twice)
G91 G1 X2 F150
M98 P8101
G90
M99
O8101
G91 G1 Y1
G90
M99
O8200 (returns to a label of its caller)
G1 X1 Y1 F100
M99 P30

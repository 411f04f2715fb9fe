%
O0200 (a subprogram in its own file)
G1 X10 Y10 F150
G2 X20 Y10 I5 J0
M99
%

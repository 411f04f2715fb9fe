%
O0001 (the Fanuc twin of tests/oracle/cases/macro_twin_fanuc.ngc)
G21 G90 G17
#100 = 0 (row)
WHILE [#100 LT 2] DO 1
  #101 = 0 (column)
  WHILE [#101 LT 3] DO 2
    G65 P9001 X[#101 * 10 + 5] Y[#100 * 10 + 5] Z-1 F200
    #101 = #101 + 1
  END 2
  #100 = #100 + 1
END 1
#1 = 0
N10 #1 = #1 + 1
G1 X[#1 * 3] Y40 F300
IF [#1 LT 3] GOTO 10
IF [#1 EQ 3] THEN #2 = 7
G1 Y#2
M98 P20100 (packed: twice O0100)
M98 P100 L1
#3 = #0
G1 X1 Y#3 Z2 (Y#3 is vacant: the word is left out)
IF [#3 EQ #0] THEN #4 = 1
IF [#3 EQ 0] THEN #4 = 2
G1 X#4
GOTO 20
G1 X99
N20 M98 P200
G0 Z5
M30
O9001 (drill at X Y to the depth Z with the feed F)
G0 X#24 Y#25
G0 Z2
G1 Z#26 F#9
G0 Z2
M99
O0100
G91 G1 X1 F100
G90
M99
%

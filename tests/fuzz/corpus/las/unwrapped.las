~Version
 VERS. 2.0 :
 WRAP. NO :
~Well
 NULL. -999.25 :
 WELL. W-1 : well
~Parameter
 BS.MM 215.9 : bit
~Curve
 DEPT.M :
 R1.MM :
 R2.MM :
 R3.MM :
 P1AZ.DEG :
 GR.GAPI :
~A DEPT R1 R2 R3 P1AZ GR
100.0 107 108 109 10 -999.25
100.5 107 ERR 109 11 55
100.25 1 2 3 4 5

~V
 VERS. 1.2 :
 WRAP. YES :
~C
 DEPT.FT :
 C1.IN :
 C2.IN :
 DEVI.RAD :
~A
1000
 8.5 8.6
 0.1
1000.5
 8.4 ***

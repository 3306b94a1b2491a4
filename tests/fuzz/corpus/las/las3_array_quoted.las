~Version
 VERS. 3.0 : v
 WRAP. NO : w
 DLM. COMMA : d
~Log_Definition
 DEPT.M : depth {F}
 FING[1].IN : f {AF}
 FING[2].IN : f {AF}
 FING[3].IN : f {AF}
 LITH. : lithology {S}
~Log_Data | Log_Definition
1.0,4.1,4.2,4.3,"SAND, SHALY"
1.1,4.2,4.3,4.4,SAND

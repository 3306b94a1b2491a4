~Version
 VERS. 3.0 :
 DLM. COMMA :
~Log_Parameter
 BS.IN 8.5 :
~Log_Definition
 DEPT.M : {F}
 FING[1].MM : {F}
 FING[2].MM : {F}
 FING[3].MM : {F}
 NOTE. : {S}
~Log_Data | Log_Definition
1.0, 100, 101, 102, a b
1.1, 100, 101, 102, c
~Core_Definition
 TOP.M :

// Ksm.g4 — grammar of the ksmc domain language (see docs/language.md).
// The C++ parser generated from this file is checked in under grammar/generated/
// together with a stamp holding this file's SHA-256 (see grammar/CMakeLists.txt).
grammar Ksm;

file : item* EOF ;

item
  : 'domain' IDENT ';'                                                   # domainItem
  | 'include' STRING ';'                                                 # includeItem
  | 'type' IDENT ('=' '{' IDENT (',' IDENT)* '}')? ';'                   # typeItem
  | kind=('evidence' | 'query') predSig (',' predSig)* ';'               # predItem
  | 'quantity' IDENT ('[' unitDef (',' unitDef)* ']')? ';'               # quantityItem
  | 'value' IDENT (',' IDENT)* ';'                                       # valueItem
  | 'extern' 'model' '(' modelSlot (',' modelSlot)* ')' ';'             # externModelItem
  | 'extern' externKind qualName ('(' (param (',' param)*)? ')')?
      ('->' typeRef)? ('reads' reads=typeRef)? moveSpec? ';'            # externItem
  | ruleName? ruleHead ruleBody '.'                                      # ruleItem
  | 'model' IDENT '{' modelVar* '}'                                      # modelItem
  | 'extract' atom '=' call ';'                                          # extractItem
  | 'prior' priorForm ';'                                                # priorItem
  | 'likelihood' call ';'                                                # likelihoodItem
  | 'output' call ';'                                                    # outputItem
  | 'kernel' 'pair' IDENT '/' IDENT kernelParams? ('=' call (',' call)*)? ';' # kernelPairItem
  | 'kernel' IDENT kernelParams? ('reverse' IDENT)? ('=' call (',' call)*)? ';' # kernelItem
  | 'schedule' '{' (scheduleRow* | scheduleEntry (',' scheduleEntry)*) '}'  # scheduleItem
  ;

externKind : IDENT | 'prior' | 'likelihood' | 'kernel' | 'output' ;
predSig  : IDENT '(' predArg (',' predArg)* ')' ;
predArg  : IDENT excl='!'? ;
unitDef  : IDENT '=' number ;
qualName : IDENT ('.' IDENT)* ;
param    : IDENT ':' typeRef paramRange? rowSum? ('=' expr)? ;
typeRef  : name=(IDENT | 'query' | 'evidence') dim*                      # namedType
         | 'set' '<' elem=(IDENT | 'query' | 'evidence') '>'             # setType
         ;
dim        : '[' NUMBER? ']' ;
// `in [1, 100]`, `in (0, inf)`, `in [0, 90 deg]`: bounds of a numeric parameter.
paramRange : 'in' lo=('[' | '(') lower=bound ',' upper=bound hi=(']' | ')') ;
bound      : number | neg='-'? 'inf' ;
// `rowsum 1`: every row of a table sums to the number (contextual word, not reserved).
rowSum     : kw=IDENT number ;
// `makes birth / death` (a move and its reverse), `makes jitter` (self-reverse),
// `serves merge, interchange` (a helper of moves other sources make).
moveSpec   : 'makes' IDENT ('/' IDENT)?                                  # makesSpec
           | 'serves' IDENT (',' IDENT)*                                 # servesSpec
           ;
// One variable of the kit's model contract: `rect[] sampled`, `se3[entity] fixed`.
modelSlot  : IDENT ('[' index=IDENT? ']')? vmode=('fixed' | 'sampled') ;

// ---- rules -----------------------------------------------------------------
// `@support hard ...`: the rule's name (generated identifiers use it).
ruleName : '@' IDENT ;
// `w 1.5:` is matched as IDENT so that `w` stays usable as a name; build checks the spelling.
ruleHead : hard='hard'? (weightProb='prob' number ':' | weightRaw=IDENT number ':')? ;
ruleBody : 'exactly' 'one' 'of' atom (',' atom)+                         # exactlyOneBody
         | formula                                                       # formulaBody
         ;
formula     : implication ('<=>' implication)* ;
implication : disjunction ('=>' disjunction)* ;
disjunction : conjunction ('v' conjunction)* ;
conjunction : unary ('^' unary)* ;
unary       : '!' unary                                                  # notFormula
            | 'exists' IDENT (',' IDENT)* ':' formula                    # existsFormula
            | atom                                                       # atomFormula
            | '(' formula ')'                                            # parenFormula
            ;
atom : IDENT '(' IDENT (',' IDENT)* ')' ;

// ---- model, extraction, prior, likelihood, kernels, schedule --------------
modelVar     : IDENT '[' index=IDENT? ']' ':' typeRef vmode=('fixed' | 'sampled') ';'
             | IDENT ':' typeRef vmode=('fixed' | 'sampled') ';'
             ;
priorForm    : 'for' IDENT (',' IDENT)* ('where' condition ('and' condition)*)? ':' call
             | call
             ;
condition    : IDENT '(' atom ')' op=('>' | '>=' | '<' | '<=') number    # probCondition
             | neg='!'? atom                                             # atomCondition
             ;
kernelParams : '(' kparam (',' kparam)* ')' ;
kparam       : IDENT ':' IDENT ;
scheduleRow  : ('[' lo=number ',' hi=rangeEnd ')' ':')? '{' (scheduleEntry (',' scheduleEntry)*)? '}' ';'? ;
rangeEnd     : number | 'inf' ;
scheduleEntry: IDENT ':' number ;

call : qualName ('(' (arg (',' arg)*)? ')')? ;
arg  : (IDENT '=')? expr ;
expr : number                                                            # numberExpr
     | STRING                                                            # stringExpr
     | ('true' | 'false')                                                # boolExpr
     | 'inf'                                                             # infExpr
     | IDENT '[' IDENT ']'                                               # indexExpr
     | qualName '(' (arg (',' arg)*)? ')'                                # callExpr
     | IDENT                                                             # nameExpr
     | '[' (expr (',' expr)*)? ']'                                       # listExpr
     | '{' (expr (',' expr)*)? '}'                                       # setExpr
     ;
number : '-'? NUMBER unit=IDENT? ;

// ---- lexer -------------------------------------------------------------------
NUMBER        : DIGIT+ ('.' DIGIT+)? ([eE] [+-]? DIGIT+)? ;
IDENT         : [A-Za-z_] [A-Za-z_0-9]* ;
STRING        : '"' (~["\\\r\n] | '\\' ~[\r\n])* '"' ;
LINE_COMMENT  : '//' ~[\r\n]* -> channel(HIDDEN) ;
BLOCK_COMMENT : '/*' .*? '*/' -> channel(HIDDEN) ;
WS            : [ \t\r\n]+ -> skip ;
ERRCHAR       : . ;
fragment DIGIT : [0-9] ;

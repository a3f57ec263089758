
// Generated from Ksm.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace ksmc_grammar {


class  KsmParser : public antlr4::Parser {
public:
  enum {
    T__0 = 1, T__1 = 2, T__2 = 3, T__3 = 4, T__4 = 5, T__5 = 6, T__6 = 7, 
    T__7 = 8, T__8 = 9, T__9 = 10, T__10 = 11, T__11 = 12, T__12 = 13, T__13 = 14, 
    T__14 = 15, T__15 = 16, T__16 = 17, T__17 = 18, T__18 = 19, T__19 = 20, 
    T__20 = 21, T__21 = 22, T__22 = 23, T__23 = 24, T__24 = 25, T__25 = 26, 
    T__26 = 27, T__27 = 28, T__28 = 29, T__29 = 30, T__30 = 31, T__31 = 32, 
    T__32 = 33, T__33 = 34, T__34 = 35, T__35 = 36, T__36 = 37, T__37 = 38, 
    T__38 = 39, T__39 = 40, T__40 = 41, T__41 = 42, T__42 = 43, T__43 = 44, 
    T__44 = 45, T__45 = 46, T__46 = 47, T__47 = 48, T__48 = 49, T__49 = 50, 
    T__50 = 51, T__51 = 52, T__52 = 53, T__53 = 54, T__54 = 55, T__55 = 56, 
    T__56 = 57, T__57 = 58, T__58 = 59, T__59 = 60, NUMBER = 61, IDENT = 62, 
    STRING = 63, LINE_COMMENT = 64, BLOCK_COMMENT = 65, WS = 66, ERRCHAR = 67
  };

  enum {
    RuleFile = 0, RuleItem = 1, RuleExternKind = 2, RulePredSig = 3, RulePredArg = 4, 
    RuleUnitDef = 5, RuleQualName = 6, RuleParam = 7, RuleTypeRef = 8, RuleDim = 9, 
    RuleParamRange = 10, RuleBound = 11, RuleRowSum = 12, RuleMoveSpec = 13, 
    RuleModelSlot = 14, RuleRuleName = 15, RuleRuleHead = 16, RuleRuleBody = 17, 
    RuleFormula = 18, RuleImplication = 19, RuleDisjunction = 20, RuleConjunction = 21, 
    RuleUnary = 22, RuleAtom = 23, RuleModelVar = 24, RulePriorForm = 25, 
    RuleCondition = 26, RuleKernelParams = 27, RuleKparam = 28, RuleScheduleRow = 29, 
    RuleRangeEnd = 30, RuleScheduleEntry = 31, RuleCall = 32, RuleArg = 33, 
    RuleExpr = 34, RuleNumber = 35
  };

  KsmParser(antlr4::TokenStream *input);
  ~KsmParser();

  virtual std::string getGrammarFileName() const override;
  virtual const antlr4::atn::ATN& getATN() const override { return _atn; };
  virtual const std::vector<std::string>& getTokenNames() const override { return _tokenNames; }; // deprecated: use vocabulary instead.
  virtual const std::vector<std::string>& getRuleNames() const override;
  virtual antlr4::dfa::Vocabulary& getVocabulary() const override;


  class FileContext;
  class ItemContext;
  class ExternKindContext;
  class PredSigContext;
  class PredArgContext;
  class UnitDefContext;
  class QualNameContext;
  class ParamContext;
  class TypeRefContext;
  class DimContext;
  class ParamRangeContext;
  class BoundContext;
  class RowSumContext;
  class MoveSpecContext;
  class ModelSlotContext;
  class RuleNameContext;
  class RuleHeadContext;
  class RuleBodyContext;
  class FormulaContext;
  class ImplicationContext;
  class DisjunctionContext;
  class ConjunctionContext;
  class UnaryContext;
  class AtomContext;
  class ModelVarContext;
  class PriorFormContext;
  class ConditionContext;
  class KernelParamsContext;
  class KparamContext;
  class ScheduleRowContext;
  class RangeEndContext;
  class ScheduleEntryContext;
  class CallContext;
  class ArgContext;
  class ExprContext;
  class NumberContext; 

  class  FileContext : public antlr4::ParserRuleContext {
  public:
    FileContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *EOF();
    std::vector<ItemContext *> item();
    ItemContext* item(size_t i);

   
  };

  FileContext* file();

  class  ItemContext : public antlr4::ParserRuleContext {
  public:
    ItemContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    ItemContext() = default;
    void copyFrom(ItemContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  DomainItemContext : public ItemContext {
  public:
    DomainItemContext(ItemContext *ctx);

    antlr4::tree::TerminalNode *IDENT();
  };

  class  KernelItemContext : public ItemContext {
  public:
    KernelItemContext(ItemContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
    KernelParamsContext *kernelParams();
    std::vector<CallContext *> call();
    CallContext* call(size_t i);
  };

  class  ExternModelItemContext : public ItemContext {
  public:
    ExternModelItemContext(ItemContext *ctx);

    std::vector<ModelSlotContext *> modelSlot();
    ModelSlotContext* modelSlot(size_t i);
  };

  class  KernelPairItemContext : public ItemContext {
  public:
    KernelPairItemContext(ItemContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
    KernelParamsContext *kernelParams();
    std::vector<CallContext *> call();
    CallContext* call(size_t i);
  };

  class  PriorItemContext : public ItemContext {
  public:
    PriorItemContext(ItemContext *ctx);

    PriorFormContext *priorForm();
  };

  class  TypeItemContext : public ItemContext {
  public:
    TypeItemContext(ItemContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
  };

  class  ScheduleItemContext : public ItemContext {
  public:
    ScheduleItemContext(ItemContext *ctx);

    std::vector<ScheduleEntryContext *> scheduleEntry();
    ScheduleEntryContext* scheduleEntry(size_t i);
    std::vector<ScheduleRowContext *> scheduleRow();
    ScheduleRowContext* scheduleRow(size_t i);
  };

  class  LikelihoodItemContext : public ItemContext {
  public:
    LikelihoodItemContext(ItemContext *ctx);

    CallContext *call();
  };

  class  PredItemContext : public ItemContext {
  public:
    PredItemContext(ItemContext *ctx);

    antlr4::Token *kind = nullptr;
    std::vector<PredSigContext *> predSig();
    PredSigContext* predSig(size_t i);
  };

  class  ValueItemContext : public ItemContext {
  public:
    ValueItemContext(ItemContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
  };

  class  RuleItemContext : public ItemContext {
  public:
    RuleItemContext(ItemContext *ctx);

    RuleHeadContext *ruleHead();
    RuleBodyContext *ruleBody();
    RuleNameContext *ruleName();
  };

  class  ExtractItemContext : public ItemContext {
  public:
    ExtractItemContext(ItemContext *ctx);

    AtomContext *atom();
    CallContext *call();
  };

  class  ExternItemContext : public ItemContext {
  public:
    ExternItemContext(ItemContext *ctx);

    KsmParser::TypeRefContext *reads = nullptr;
    ExternKindContext *externKind();
    QualNameContext *qualName();
    std::vector<TypeRefContext *> typeRef();
    TypeRefContext* typeRef(size_t i);
    MoveSpecContext *moveSpec();
    std::vector<ParamContext *> param();
    ParamContext* param(size_t i);
  };

  class  OutputItemContext : public ItemContext {
  public:
    OutputItemContext(ItemContext *ctx);

    CallContext *call();
  };

  class  IncludeItemContext : public ItemContext {
  public:
    IncludeItemContext(ItemContext *ctx);

    antlr4::tree::TerminalNode *STRING();
  };

  class  QuantityItemContext : public ItemContext {
  public:
    QuantityItemContext(ItemContext *ctx);

    antlr4::tree::TerminalNode *IDENT();
    std::vector<UnitDefContext *> unitDef();
    UnitDefContext* unitDef(size_t i);
  };

  class  ModelItemContext : public ItemContext {
  public:
    ModelItemContext(ItemContext *ctx);

    antlr4::tree::TerminalNode *IDENT();
    std::vector<ModelVarContext *> modelVar();
    ModelVarContext* modelVar(size_t i);
  };

  ItemContext* item();

  class  ExternKindContext : public antlr4::ParserRuleContext {
  public:
    ExternKindContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IDENT();

   
  };

  ExternKindContext* externKind();

  class  PredSigContext : public antlr4::ParserRuleContext {
  public:
    PredSigContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IDENT();
    std::vector<PredArgContext *> predArg();
    PredArgContext* predArg(size_t i);

   
  };

  PredSigContext* predSig();

  class  PredArgContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *excl = nullptr;;
    PredArgContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IDENT();

   
  };

  PredArgContext* predArg();

  class  UnitDefContext : public antlr4::ParserRuleContext {
  public:
    UnitDefContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IDENT();
    NumberContext *number();

   
  };

  UnitDefContext* unitDef();

  class  QualNameContext : public antlr4::ParserRuleContext {
  public:
    QualNameContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);

   
  };

  QualNameContext* qualName();

  class  ParamContext : public antlr4::ParserRuleContext {
  public:
    ParamContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IDENT();
    TypeRefContext *typeRef();
    ParamRangeContext *paramRange();
    RowSumContext *rowSum();
    ExprContext *expr();

   
  };

  ParamContext* param();

  class  TypeRefContext : public antlr4::ParserRuleContext {
  public:
    TypeRefContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    TypeRefContext() = default;
    void copyFrom(TypeRefContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  NamedTypeContext : public TypeRefContext {
  public:
    NamedTypeContext(TypeRefContext *ctx);

    antlr4::Token *name = nullptr;
    antlr4::tree::TerminalNode *IDENT();
    std::vector<DimContext *> dim();
    DimContext* dim(size_t i);
  };

  class  SetTypeContext : public TypeRefContext {
  public:
    SetTypeContext(TypeRefContext *ctx);

    antlr4::Token *elem = nullptr;
    antlr4::tree::TerminalNode *IDENT();
  };

  TypeRefContext* typeRef();

  class  DimContext : public antlr4::ParserRuleContext {
  public:
    DimContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *NUMBER();

   
  };

  DimContext* dim();

  class  ParamRangeContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *lo = nullptr;;
    KsmParser::BoundContext *lower = nullptr;;
    KsmParser::BoundContext *upper = nullptr;;
    antlr4::Token *hi = nullptr;;
    ParamRangeContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<BoundContext *> bound();
    BoundContext* bound(size_t i);

   
  };

  ParamRangeContext* paramRange();

  class  BoundContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *neg = nullptr;;
    BoundContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    NumberContext *number();

   
  };

  BoundContext* bound();

  class  RowSumContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *kw = nullptr;;
    RowSumContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    NumberContext *number();
    antlr4::tree::TerminalNode *IDENT();

   
  };

  RowSumContext* rowSum();

  class  MoveSpecContext : public antlr4::ParserRuleContext {
  public:
    MoveSpecContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    MoveSpecContext() = default;
    void copyFrom(MoveSpecContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  MakesSpecContext : public MoveSpecContext {
  public:
    MakesSpecContext(MoveSpecContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
  };

  class  ServesSpecContext : public MoveSpecContext {
  public:
    ServesSpecContext(MoveSpecContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
  };

  MoveSpecContext* moveSpec();

  class  ModelSlotContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *index = nullptr;;
    antlr4::Token *vmode = nullptr;;
    ModelSlotContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);

   
  };

  ModelSlotContext* modelSlot();

  class  RuleNameContext : public antlr4::ParserRuleContext {
  public:
    RuleNameContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IDENT();

   
  };

  RuleNameContext* ruleName();

  class  RuleHeadContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *hard = nullptr;;
    antlr4::Token *weightProb = nullptr;;
    antlr4::Token *weightRaw = nullptr;;
    RuleHeadContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    NumberContext *number();
    antlr4::tree::TerminalNode *IDENT();

   
  };

  RuleHeadContext* ruleHead();

  class  RuleBodyContext : public antlr4::ParserRuleContext {
  public:
    RuleBodyContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    RuleBodyContext() = default;
    void copyFrom(RuleBodyContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  FormulaBodyContext : public RuleBodyContext {
  public:
    FormulaBodyContext(RuleBodyContext *ctx);

    FormulaContext *formula();
  };

  class  ExactlyOneBodyContext : public RuleBodyContext {
  public:
    ExactlyOneBodyContext(RuleBodyContext *ctx);

    std::vector<AtomContext *> atom();
    AtomContext* atom(size_t i);
  };

  RuleBodyContext* ruleBody();

  class  FormulaContext : public antlr4::ParserRuleContext {
  public:
    FormulaContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<ImplicationContext *> implication();
    ImplicationContext* implication(size_t i);

   
  };

  FormulaContext* formula();

  class  ImplicationContext : public antlr4::ParserRuleContext {
  public:
    ImplicationContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<DisjunctionContext *> disjunction();
    DisjunctionContext* disjunction(size_t i);

   
  };

  ImplicationContext* implication();

  class  DisjunctionContext : public antlr4::ParserRuleContext {
  public:
    DisjunctionContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<ConjunctionContext *> conjunction();
    ConjunctionContext* conjunction(size_t i);

   
  };

  DisjunctionContext* disjunction();

  class  ConjunctionContext : public antlr4::ParserRuleContext {
  public:
    ConjunctionContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<UnaryContext *> unary();
    UnaryContext* unary(size_t i);

   
  };

  ConjunctionContext* conjunction();

  class  UnaryContext : public antlr4::ParserRuleContext {
  public:
    UnaryContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    UnaryContext() = default;
    void copyFrom(UnaryContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  ParenFormulaContext : public UnaryContext {
  public:
    ParenFormulaContext(UnaryContext *ctx);

    FormulaContext *formula();
  };

  class  AtomFormulaContext : public UnaryContext {
  public:
    AtomFormulaContext(UnaryContext *ctx);

    AtomContext *atom();
  };

  class  NotFormulaContext : public UnaryContext {
  public:
    NotFormulaContext(UnaryContext *ctx);

    UnaryContext *unary();
  };

  class  ExistsFormulaContext : public UnaryContext {
  public:
    ExistsFormulaContext(UnaryContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
    FormulaContext *formula();
  };

  UnaryContext* unary();

  class  AtomContext : public antlr4::ParserRuleContext {
  public:
    AtomContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);

   
  };

  AtomContext* atom();

  class  ModelVarContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *index = nullptr;;
    antlr4::Token *vmode = nullptr;;
    ModelVarContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
    TypeRefContext *typeRef();

   
  };

  ModelVarContext* modelVar();

  class  PriorFormContext : public antlr4::ParserRuleContext {
  public:
    PriorFormContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
    CallContext *call();
    std::vector<ConditionContext *> condition();
    ConditionContext* condition(size_t i);

   
  };

  PriorFormContext* priorForm();

  class  ConditionContext : public antlr4::ParserRuleContext {
  public:
    ConditionContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    ConditionContext() = default;
    void copyFrom(ConditionContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  AtomConditionContext : public ConditionContext {
  public:
    AtomConditionContext(ConditionContext *ctx);

    antlr4::Token *neg = nullptr;
    AtomContext *atom();
  };

  class  ProbConditionContext : public ConditionContext {
  public:
    ProbConditionContext(ConditionContext *ctx);

    antlr4::Token *op = nullptr;
    antlr4::tree::TerminalNode *IDENT();
    AtomContext *atom();
    NumberContext *number();
  };

  ConditionContext* condition();

  class  KernelParamsContext : public antlr4::ParserRuleContext {
  public:
    KernelParamsContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<KparamContext *> kparam();
    KparamContext* kparam(size_t i);

   
  };

  KernelParamsContext* kernelParams();

  class  KparamContext : public antlr4::ParserRuleContext {
  public:
    KparamContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);

   
  };

  KparamContext* kparam();

  class  ScheduleRowContext : public antlr4::ParserRuleContext {
  public:
    KsmParser::NumberContext *lo = nullptr;;
    KsmParser::RangeEndContext *hi = nullptr;;
    ScheduleRowContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<ScheduleEntryContext *> scheduleEntry();
    ScheduleEntryContext* scheduleEntry(size_t i);
    NumberContext *number();
    RangeEndContext *rangeEnd();

   
  };

  ScheduleRowContext* scheduleRow();

  class  RangeEndContext : public antlr4::ParserRuleContext {
  public:
    RangeEndContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    NumberContext *number();

   
  };

  RangeEndContext* rangeEnd();

  class  ScheduleEntryContext : public antlr4::ParserRuleContext {
  public:
    ScheduleEntryContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IDENT();
    NumberContext *number();

   
  };

  ScheduleEntryContext* scheduleEntry();

  class  CallContext : public antlr4::ParserRuleContext {
  public:
    CallContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    QualNameContext *qualName();
    std::vector<ArgContext *> arg();
    ArgContext* arg(size_t i);

   
  };

  CallContext* call();

  class  ArgContext : public antlr4::ParserRuleContext {
  public:
    ArgContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    ExprContext *expr();
    antlr4::tree::TerminalNode *IDENT();

   
  };

  ArgContext* arg();

  class  ExprContext : public antlr4::ParserRuleContext {
  public:
    ExprContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    ExprContext() = default;
    void copyFrom(ExprContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  StringExprContext : public ExprContext {
  public:
    StringExprContext(ExprContext *ctx);

    antlr4::tree::TerminalNode *STRING();
  };

  class  IndexExprContext : public ExprContext {
  public:
    IndexExprContext(ExprContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> IDENT();
    antlr4::tree::TerminalNode* IDENT(size_t i);
  };

  class  NumberExprContext : public ExprContext {
  public:
    NumberExprContext(ExprContext *ctx);

    NumberContext *number();
  };

  class  InfExprContext : public ExprContext {
  public:
    InfExprContext(ExprContext *ctx);

  };

  class  BoolExprContext : public ExprContext {
  public:
    BoolExprContext(ExprContext *ctx);

  };

  class  CallExprContext : public ExprContext {
  public:
    CallExprContext(ExprContext *ctx);

    QualNameContext *qualName();
    std::vector<ArgContext *> arg();
    ArgContext* arg(size_t i);
  };

  class  ListExprContext : public ExprContext {
  public:
    ListExprContext(ExprContext *ctx);

    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
  };

  class  NameExprContext : public ExprContext {
  public:
    NameExprContext(ExprContext *ctx);

    antlr4::tree::TerminalNode *IDENT();
  };

  class  SetExprContext : public ExprContext {
  public:
    SetExprContext(ExprContext *ctx);

    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
  };

  ExprContext* expr();

  class  NumberContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *unit = nullptr;;
    NumberContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *NUMBER();
    antlr4::tree::TerminalNode *IDENT();

   
  };

  NumberContext* number();


private:
  static std::vector<antlr4::dfa::DFA> _decisionToDFA;
  static antlr4::atn::PredictionContextCache _sharedContextCache;
  static std::vector<std::string> _ruleNames;
  static std::vector<std::string> _tokenNames;

  static std::vector<std::string> _literalNames;
  static std::vector<std::string> _symbolicNames;
  static antlr4::dfa::Vocabulary _vocabulary;
  static antlr4::atn::ATN _atn;
  static std::vector<uint16_t> _serializedATN;


  struct Initializer {
    Initializer();
  };
  static Initializer _init;
};

}  // namespace ksmc_grammar

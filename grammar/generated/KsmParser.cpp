
// Generated from Ksm.g4 by ANTLR 4.7.2



#include "KsmParser.h"


using namespace antlrcpp;
using namespace ksmc_grammar;
using namespace antlr4;

KsmParser::KsmParser(TokenStream *input) : Parser(input) {
  _interpreter = new atn::ParserATNSimulator(this, _atn, _decisionToDFA, _sharedContextCache);
}

KsmParser::~KsmParser() {
  delete _interpreter;
}

std::string KsmParser::getGrammarFileName() const {
  return "Ksm.g4";
}

const std::vector<std::string>& KsmParser::getRuleNames() const {
  return _ruleNames;
}

dfa::Vocabulary& KsmParser::getVocabulary() const {
  return _vocabulary;
}


//----------------- FileContext ------------------------------------------------------------------

KsmParser::FileContext::FileContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::FileContext::EOF() {
  return getToken(KsmParser::EOF, 0);
}

std::vector<KsmParser::ItemContext *> KsmParser::FileContext::item() {
  return getRuleContexts<KsmParser::ItemContext>();
}

KsmParser::ItemContext* KsmParser::FileContext::item(size_t i) {
  return getRuleContext<KsmParser::ItemContext>(i);
}


size_t KsmParser::FileContext::getRuleIndex() const {
  return KsmParser::RuleFile;
}


KsmParser::FileContext* KsmParser::file() {
  FileContext *_localctx = _tracker.createInstance<FileContext>(_ctx, getState());
  enterRule(_localctx, 0, KsmParser::RuleFile);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(75);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << KsmParser::T__0)
      | (1ULL << KsmParser::T__2)
      | (1ULL << KsmParser::T__3)
      | (1ULL << KsmParser::T__8)
      | (1ULL << KsmParser::T__9)
      | (1ULL << KsmParser::T__10)
      | (1ULL << KsmParser::T__13)
      | (1ULL << KsmParser::T__14)
      | (1ULL << KsmParser::T__15)
      | (1ULL << KsmParser::T__16)
      | (1ULL << KsmParser::T__21)
      | (1ULL << KsmParser::T__22)
      | (1ULL << KsmParser::T__23)
      | (1ULL << KsmParser::T__24)
      | (1ULL << KsmParser::T__25)
      | (1ULL << KsmParser::T__29)
      | (1ULL << KsmParser::T__30)
      | (1ULL << KsmParser::T__42)
      | (1ULL << KsmParser::T__43)
      | (1ULL << KsmParser::T__44)
      | (1ULL << KsmParser::T__45)
      | (1ULL << KsmParser::T__52)
      | (1ULL << KsmParser::IDENT))) != 0)) {
      setState(72);
      item();
      setState(77);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(78);
    match(KsmParser::EOF);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ItemContext ------------------------------------------------------------------

KsmParser::ItemContext::ItemContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t KsmParser::ItemContext::getRuleIndex() const {
  return KsmParser::RuleItem;
}

void KsmParser::ItemContext::copyFrom(ItemContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- DomainItemContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::DomainItemContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

KsmParser::DomainItemContext::DomainItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- KernelItemContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> KsmParser::KernelItemContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::KernelItemContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::KernelParamsContext* KsmParser::KernelItemContext::kernelParams() {
  return getRuleContext<KsmParser::KernelParamsContext>(0);
}

std::vector<KsmParser::CallContext *> KsmParser::KernelItemContext::call() {
  return getRuleContexts<KsmParser::CallContext>();
}

KsmParser::CallContext* KsmParser::KernelItemContext::call(size_t i) {
  return getRuleContext<KsmParser::CallContext>(i);
}

KsmParser::KernelItemContext::KernelItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- ExternModelItemContext ------------------------------------------------------------------

std::vector<KsmParser::ModelSlotContext *> KsmParser::ExternModelItemContext::modelSlot() {
  return getRuleContexts<KsmParser::ModelSlotContext>();
}

KsmParser::ModelSlotContext* KsmParser::ExternModelItemContext::modelSlot(size_t i) {
  return getRuleContext<KsmParser::ModelSlotContext>(i);
}

KsmParser::ExternModelItemContext::ExternModelItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- KernelPairItemContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> KsmParser::KernelPairItemContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::KernelPairItemContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::KernelParamsContext* KsmParser::KernelPairItemContext::kernelParams() {
  return getRuleContext<KsmParser::KernelParamsContext>(0);
}

std::vector<KsmParser::CallContext *> KsmParser::KernelPairItemContext::call() {
  return getRuleContexts<KsmParser::CallContext>();
}

KsmParser::CallContext* KsmParser::KernelPairItemContext::call(size_t i) {
  return getRuleContext<KsmParser::CallContext>(i);
}

KsmParser::KernelPairItemContext::KernelPairItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- PriorItemContext ------------------------------------------------------------------

KsmParser::PriorFormContext* KsmParser::PriorItemContext::priorForm() {
  return getRuleContext<KsmParser::PriorFormContext>(0);
}

KsmParser::PriorItemContext::PriorItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- TypeItemContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> KsmParser::TypeItemContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::TypeItemContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::TypeItemContext::TypeItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- ScheduleItemContext ------------------------------------------------------------------

std::vector<KsmParser::ScheduleEntryContext *> KsmParser::ScheduleItemContext::scheduleEntry() {
  return getRuleContexts<KsmParser::ScheduleEntryContext>();
}

KsmParser::ScheduleEntryContext* KsmParser::ScheduleItemContext::scheduleEntry(size_t i) {
  return getRuleContext<KsmParser::ScheduleEntryContext>(i);
}

std::vector<KsmParser::ScheduleRowContext *> KsmParser::ScheduleItemContext::scheduleRow() {
  return getRuleContexts<KsmParser::ScheduleRowContext>();
}

KsmParser::ScheduleRowContext* KsmParser::ScheduleItemContext::scheduleRow(size_t i) {
  return getRuleContext<KsmParser::ScheduleRowContext>(i);
}

KsmParser::ScheduleItemContext::ScheduleItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- LikelihoodItemContext ------------------------------------------------------------------

KsmParser::CallContext* KsmParser::LikelihoodItemContext::call() {
  return getRuleContext<KsmParser::CallContext>(0);
}

KsmParser::LikelihoodItemContext::LikelihoodItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- PredItemContext ------------------------------------------------------------------

std::vector<KsmParser::PredSigContext *> KsmParser::PredItemContext::predSig() {
  return getRuleContexts<KsmParser::PredSigContext>();
}

KsmParser::PredSigContext* KsmParser::PredItemContext::predSig(size_t i) {
  return getRuleContext<KsmParser::PredSigContext>(i);
}

KsmParser::PredItemContext::PredItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- ValueItemContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> KsmParser::ValueItemContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::ValueItemContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::ValueItemContext::ValueItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- RuleItemContext ------------------------------------------------------------------

KsmParser::RuleHeadContext* KsmParser::RuleItemContext::ruleHead() {
  return getRuleContext<KsmParser::RuleHeadContext>(0);
}

KsmParser::RuleBodyContext* KsmParser::RuleItemContext::ruleBody() {
  return getRuleContext<KsmParser::RuleBodyContext>(0);
}

KsmParser::RuleNameContext* KsmParser::RuleItemContext::ruleName() {
  return getRuleContext<KsmParser::RuleNameContext>(0);
}

KsmParser::RuleItemContext::RuleItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- ExtractItemContext ------------------------------------------------------------------

KsmParser::AtomContext* KsmParser::ExtractItemContext::atom() {
  return getRuleContext<KsmParser::AtomContext>(0);
}

KsmParser::CallContext* KsmParser::ExtractItemContext::call() {
  return getRuleContext<KsmParser::CallContext>(0);
}

KsmParser::ExtractItemContext::ExtractItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- ExternItemContext ------------------------------------------------------------------

KsmParser::ExternKindContext* KsmParser::ExternItemContext::externKind() {
  return getRuleContext<KsmParser::ExternKindContext>(0);
}

KsmParser::QualNameContext* KsmParser::ExternItemContext::qualName() {
  return getRuleContext<KsmParser::QualNameContext>(0);
}

std::vector<KsmParser::TypeRefContext *> KsmParser::ExternItemContext::typeRef() {
  return getRuleContexts<KsmParser::TypeRefContext>();
}

KsmParser::TypeRefContext* KsmParser::ExternItemContext::typeRef(size_t i) {
  return getRuleContext<KsmParser::TypeRefContext>(i);
}

KsmParser::MoveSpecContext* KsmParser::ExternItemContext::moveSpec() {
  return getRuleContext<KsmParser::MoveSpecContext>(0);
}

std::vector<KsmParser::ParamContext *> KsmParser::ExternItemContext::param() {
  return getRuleContexts<KsmParser::ParamContext>();
}

KsmParser::ParamContext* KsmParser::ExternItemContext::param(size_t i) {
  return getRuleContext<KsmParser::ParamContext>(i);
}

KsmParser::ExternItemContext::ExternItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- OutputItemContext ------------------------------------------------------------------

KsmParser::CallContext* KsmParser::OutputItemContext::call() {
  return getRuleContext<KsmParser::CallContext>(0);
}

KsmParser::OutputItemContext::OutputItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- IncludeItemContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::IncludeItemContext::STRING() {
  return getToken(KsmParser::STRING, 0);
}

KsmParser::IncludeItemContext::IncludeItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- QuantityItemContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::QuantityItemContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

std::vector<KsmParser::UnitDefContext *> KsmParser::QuantityItemContext::unitDef() {
  return getRuleContexts<KsmParser::UnitDefContext>();
}

KsmParser::UnitDefContext* KsmParser::QuantityItemContext::unitDef(size_t i) {
  return getRuleContext<KsmParser::UnitDefContext>(i);
}

KsmParser::QuantityItemContext::QuantityItemContext(ItemContext *ctx) { copyFrom(ctx); }


//----------------- ModelItemContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::ModelItemContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

std::vector<KsmParser::ModelVarContext *> KsmParser::ModelItemContext::modelVar() {
  return getRuleContexts<KsmParser::ModelVarContext>();
}

KsmParser::ModelVarContext* KsmParser::ModelItemContext::modelVar(size_t i) {
  return getRuleContext<KsmParser::ModelVarContext>(i);
}

KsmParser::ModelItemContext::ModelItemContext(ItemContext *ctx) { copyFrom(ctx); }


KsmParser::ItemContext* KsmParser::item() {
  ItemContext *_localctx = _tracker.createInstance<ItemContext>(_ctx, getState());
  enterRule(_localctx, 2, KsmParser::RuleItem);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(278);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 26, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::DomainItemContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(80);
      match(KsmParser::T__0);
      setState(81);
      match(KsmParser::IDENT);
      setState(82);
      match(KsmParser::T__1);
      break;
    }

    case 2: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::IncludeItemContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(83);
      match(KsmParser::T__2);
      setState(84);
      match(KsmParser::STRING);
      setState(85);
      match(KsmParser::T__1);
      break;
    }

    case 3: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::TypeItemContext>(_localctx));
      enterOuterAlt(_localctx, 3);
      setState(86);
      match(KsmParser::T__3);
      setState(87);
      match(KsmParser::IDENT);
      setState(99);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__4) {
        setState(88);
        match(KsmParser::T__4);
        setState(89);
        match(KsmParser::T__5);
        setState(90);
        match(KsmParser::IDENT);
        setState(95);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(91);
          match(KsmParser::T__6);
          setState(92);
          match(KsmParser::IDENT);
          setState(97);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(98);
        match(KsmParser::T__7);
      }
      setState(101);
      match(KsmParser::T__1);
      break;
    }

    case 4: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::PredItemContext>(_localctx));
      enterOuterAlt(_localctx, 4);
      setState(102);
      dynamic_cast<PredItemContext *>(_localctx)->kind = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == KsmParser::T__8

      || _la == KsmParser::T__9)) {
        dynamic_cast<PredItemContext *>(_localctx)->kind = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(103);
      predSig();
      setState(108);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::T__6) {
        setState(104);
        match(KsmParser::T__6);
        setState(105);
        predSig();
        setState(110);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(111);
      match(KsmParser::T__1);
      break;
    }

    case 5: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::QuantityItemContext>(_localctx));
      enterOuterAlt(_localctx, 5);
      setState(113);
      match(KsmParser::T__10);
      setState(114);
      match(KsmParser::IDENT);
      setState(126);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__11) {
        setState(115);
        match(KsmParser::T__11);
        setState(116);
        unitDef();
        setState(121);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(117);
          match(KsmParser::T__6);
          setState(118);
          unitDef();
          setState(123);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(124);
        match(KsmParser::T__12);
      }
      setState(128);
      match(KsmParser::T__1);
      break;
    }

    case 6: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ValueItemContext>(_localctx));
      enterOuterAlt(_localctx, 6);
      setState(129);
      match(KsmParser::T__13);
      setState(130);
      match(KsmParser::IDENT);
      setState(135);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::T__6) {
        setState(131);
        match(KsmParser::T__6);
        setState(132);
        match(KsmParser::IDENT);
        setState(137);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(138);
      match(KsmParser::T__1);
      break;
    }

    case 7: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ExternModelItemContext>(_localctx));
      enterOuterAlt(_localctx, 7);
      setState(139);
      match(KsmParser::T__14);
      setState(140);
      match(KsmParser::T__15);
      setState(141);
      match(KsmParser::T__16);
      setState(142);
      modelSlot();
      setState(147);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::T__6) {
        setState(143);
        match(KsmParser::T__6);
        setState(144);
        modelSlot();
        setState(149);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(150);
      match(KsmParser::T__17);
      setState(151);
      match(KsmParser::T__1);
      break;
    }

    case 8: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ExternItemContext>(_localctx));
      enterOuterAlt(_localctx, 8);
      setState(153);
      match(KsmParser::T__14);
      setState(154);
      externKind();
      setState(155);
      qualName();
      setState(168);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__16) {
        setState(156);
        match(KsmParser::T__16);
        setState(165);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == KsmParser::IDENT) {
          setState(157);
          param();
          setState(162);
          _errHandler->sync(this);
          _la = _input->LA(1);
          while (_la == KsmParser::T__6) {
            setState(158);
            match(KsmParser::T__6);
            setState(159);
            param();
            setState(164);
            _errHandler->sync(this);
            _la = _input->LA(1);
          }
        }
        setState(167);
        match(KsmParser::T__17);
      }
      setState(172);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__18) {
        setState(170);
        match(KsmParser::T__18);
        setState(171);
        typeRef();
      }
      setState(176);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__19) {
        setState(174);
        match(KsmParser::T__19);
        setState(175);
        dynamic_cast<ExternItemContext *>(_localctx)->reads = typeRef();
      }
      setState(179);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__38

      || _la == KsmParser::T__39) {
        setState(178);
        moveSpec();
      }
      setState(181);
      match(KsmParser::T__1);
      break;
    }

    case 9: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::RuleItemContext>(_localctx));
      enterOuterAlt(_localctx, 9);
      setState(184);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__42) {
        setState(183);
        ruleName();
      }
      setState(186);
      ruleHead();
      setState(187);
      ruleBody();
      setState(188);
      match(KsmParser::T__20);
      break;
    }

    case 10: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ModelItemContext>(_localctx));
      enterOuterAlt(_localctx, 10);
      setState(190);
      match(KsmParser::T__15);
      setState(191);
      match(KsmParser::IDENT);
      setState(192);
      match(KsmParser::T__5);
      setState(196);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::IDENT) {
        setState(193);
        modelVar();
        setState(198);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(199);
      match(KsmParser::T__7);
      break;
    }

    case 11: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ExtractItemContext>(_localctx));
      enterOuterAlt(_localctx, 11);
      setState(200);
      match(KsmParser::T__21);
      setState(201);
      atom();
      setState(202);
      match(KsmParser::T__4);
      setState(203);
      call();
      setState(204);
      match(KsmParser::T__1);
      break;
    }

    case 12: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::PriorItemContext>(_localctx));
      enterOuterAlt(_localctx, 12);
      setState(206);
      match(KsmParser::T__22);
      setState(207);
      priorForm();
      setState(208);
      match(KsmParser::T__1);
      break;
    }

    case 13: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::LikelihoodItemContext>(_localctx));
      enterOuterAlt(_localctx, 13);
      setState(210);
      match(KsmParser::T__23);
      setState(211);
      call();
      setState(212);
      match(KsmParser::T__1);
      break;
    }

    case 14: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::OutputItemContext>(_localctx));
      enterOuterAlt(_localctx, 14);
      setState(214);
      match(KsmParser::T__24);
      setState(215);
      call();
      setState(216);
      match(KsmParser::T__1);
      break;
    }

    case 15: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::KernelPairItemContext>(_localctx));
      enterOuterAlt(_localctx, 15);
      setState(218);
      match(KsmParser::T__25);
      setState(219);
      match(KsmParser::T__26);
      setState(220);
      match(KsmParser::IDENT);
      setState(221);
      match(KsmParser::T__27);
      setState(222);
      match(KsmParser::IDENT);
      setState(224);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__16) {
        setState(223);
        kernelParams();
      }
      setState(235);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__4) {
        setState(226);
        match(KsmParser::T__4);
        setState(227);
        call();
        setState(232);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(228);
          match(KsmParser::T__6);
          setState(229);
          call();
          setState(234);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(237);
      match(KsmParser::T__1);
      break;
    }

    case 16: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::KernelItemContext>(_localctx));
      enterOuterAlt(_localctx, 16);
      setState(238);
      match(KsmParser::T__25);
      setState(239);
      match(KsmParser::IDENT);
      setState(241);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__16) {
        setState(240);
        kernelParams();
      }
      setState(245);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__28) {
        setState(243);
        match(KsmParser::T__28);
        setState(244);
        match(KsmParser::IDENT);
      }
      setState(256);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__4) {
        setState(247);
        match(KsmParser::T__4);
        setState(248);
        call();
        setState(253);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(249);
          match(KsmParser::T__6);
          setState(250);
          call();
          setState(255);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(258);
      match(KsmParser::T__1);
      break;
    }

    case 17: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ScheduleItemContext>(_localctx));
      enterOuterAlt(_localctx, 17);
      setState(259);
      match(KsmParser::T__29);
      setState(260);
      match(KsmParser::T__5);
      setState(275);
      _errHandler->sync(this);
      switch (_input->LA(1)) {
        case KsmParser::T__5:
        case KsmParser::T__7:
        case KsmParser::T__11: {
          setState(264);
          _errHandler->sync(this);
          _la = _input->LA(1);
          while (_la == KsmParser::T__5

          || _la == KsmParser::T__11) {
            setState(261);
            scheduleRow();
            setState(266);
            _errHandler->sync(this);
            _la = _input->LA(1);
          }
          break;
        }

        case KsmParser::IDENT: {
          setState(267);
          scheduleEntry();
          setState(272);
          _errHandler->sync(this);
          _la = _input->LA(1);
          while (_la == KsmParser::T__6) {
            setState(268);
            match(KsmParser::T__6);
            setState(269);
            scheduleEntry();
            setState(274);
            _errHandler->sync(this);
            _la = _input->LA(1);
          }
          break;
        }

      default:
        throw NoViableAltException(this);
      }
      setState(277);
      match(KsmParser::T__7);
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ExternKindContext ------------------------------------------------------------------

KsmParser::ExternKindContext::ExternKindContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::ExternKindContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}


size_t KsmParser::ExternKindContext::getRuleIndex() const {
  return KsmParser::RuleExternKind;
}


KsmParser::ExternKindContext* KsmParser::externKind() {
  ExternKindContext *_localctx = _tracker.createInstance<ExternKindContext>(_ctx, getState());
  enterRule(_localctx, 4, KsmParser::RuleExternKind);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(280);
    _la = _input->LA(1);
    if (!((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << KsmParser::T__22)
      | (1ULL << KsmParser::T__23)
      | (1ULL << KsmParser::T__24)
      | (1ULL << KsmParser::T__25)
      | (1ULL << KsmParser::IDENT))) != 0))) {
    _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- PredSigContext ------------------------------------------------------------------

KsmParser::PredSigContext::PredSigContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::PredSigContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

std::vector<KsmParser::PredArgContext *> KsmParser::PredSigContext::predArg() {
  return getRuleContexts<KsmParser::PredArgContext>();
}

KsmParser::PredArgContext* KsmParser::PredSigContext::predArg(size_t i) {
  return getRuleContext<KsmParser::PredArgContext>(i);
}


size_t KsmParser::PredSigContext::getRuleIndex() const {
  return KsmParser::RulePredSig;
}


KsmParser::PredSigContext* KsmParser::predSig() {
  PredSigContext *_localctx = _tracker.createInstance<PredSigContext>(_ctx, getState());
  enterRule(_localctx, 6, KsmParser::RulePredSig);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(282);
    match(KsmParser::IDENT);
    setState(283);
    match(KsmParser::T__16);
    setState(284);
    predArg();
    setState(289);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == KsmParser::T__6) {
      setState(285);
      match(KsmParser::T__6);
      setState(286);
      predArg();
      setState(291);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(292);
    match(KsmParser::T__17);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- PredArgContext ------------------------------------------------------------------

KsmParser::PredArgContext::PredArgContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::PredArgContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}


size_t KsmParser::PredArgContext::getRuleIndex() const {
  return KsmParser::RulePredArg;
}


KsmParser::PredArgContext* KsmParser::predArg() {
  PredArgContext *_localctx = _tracker.createInstance<PredArgContext>(_ctx, getState());
  enterRule(_localctx, 8, KsmParser::RulePredArg);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(294);
    match(KsmParser::IDENT);
    setState(296);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__30) {
      setState(295);
      dynamic_cast<PredArgContext *>(_localctx)->excl = match(KsmParser::T__30);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- UnitDefContext ------------------------------------------------------------------

KsmParser::UnitDefContext::UnitDefContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::UnitDefContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

KsmParser::NumberContext* KsmParser::UnitDefContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}


size_t KsmParser::UnitDefContext::getRuleIndex() const {
  return KsmParser::RuleUnitDef;
}


KsmParser::UnitDefContext* KsmParser::unitDef() {
  UnitDefContext *_localctx = _tracker.createInstance<UnitDefContext>(_ctx, getState());
  enterRule(_localctx, 10, KsmParser::RuleUnitDef);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(298);
    match(KsmParser::IDENT);
    setState(299);
    match(KsmParser::T__4);
    setState(300);
    number();
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- QualNameContext ------------------------------------------------------------------

KsmParser::QualNameContext::QualNameContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<tree::TerminalNode *> KsmParser::QualNameContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::QualNameContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}


size_t KsmParser::QualNameContext::getRuleIndex() const {
  return KsmParser::RuleQualName;
}


KsmParser::QualNameContext* KsmParser::qualName() {
  QualNameContext *_localctx = _tracker.createInstance<QualNameContext>(_ctx, getState());
  enterRule(_localctx, 12, KsmParser::RuleQualName);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(302);
    match(KsmParser::IDENT);
    setState(307);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == KsmParser::T__20) {
      setState(303);
      match(KsmParser::T__20);
      setState(304);
      match(KsmParser::IDENT);
      setState(309);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ParamContext ------------------------------------------------------------------

KsmParser::ParamContext::ParamContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::ParamContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

KsmParser::TypeRefContext* KsmParser::ParamContext::typeRef() {
  return getRuleContext<KsmParser::TypeRefContext>(0);
}

KsmParser::ParamRangeContext* KsmParser::ParamContext::paramRange() {
  return getRuleContext<KsmParser::ParamRangeContext>(0);
}

KsmParser::RowSumContext* KsmParser::ParamContext::rowSum() {
  return getRuleContext<KsmParser::RowSumContext>(0);
}

KsmParser::ExprContext* KsmParser::ParamContext::expr() {
  return getRuleContext<KsmParser::ExprContext>(0);
}


size_t KsmParser::ParamContext::getRuleIndex() const {
  return KsmParser::RuleParam;
}


KsmParser::ParamContext* KsmParser::param() {
  ParamContext *_localctx = _tracker.createInstance<ParamContext>(_ctx, getState());
  enterRule(_localctx, 14, KsmParser::RuleParam);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(310);
    match(KsmParser::IDENT);
    setState(311);
    match(KsmParser::T__31);
    setState(312);
    typeRef();
    setState(314);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__35) {
      setState(313);
      paramRange();
    }
    setState(317);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::IDENT) {
      setState(316);
      rowSum();
    }
    setState(321);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__4) {
      setState(319);
      match(KsmParser::T__4);
      setState(320);
      expr();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- TypeRefContext ------------------------------------------------------------------

KsmParser::TypeRefContext::TypeRefContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t KsmParser::TypeRefContext::getRuleIndex() const {
  return KsmParser::RuleTypeRef;
}

void KsmParser::TypeRefContext::copyFrom(TypeRefContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- NamedTypeContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::NamedTypeContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

std::vector<KsmParser::DimContext *> KsmParser::NamedTypeContext::dim() {
  return getRuleContexts<KsmParser::DimContext>();
}

KsmParser::DimContext* KsmParser::NamedTypeContext::dim(size_t i) {
  return getRuleContext<KsmParser::DimContext>(i);
}

KsmParser::NamedTypeContext::NamedTypeContext(TypeRefContext *ctx) { copyFrom(ctx); }


//----------------- SetTypeContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::SetTypeContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

KsmParser::SetTypeContext::SetTypeContext(TypeRefContext *ctx) { copyFrom(ctx); }


KsmParser::TypeRefContext* KsmParser::typeRef() {
  TypeRefContext *_localctx = _tracker.createInstance<TypeRefContext>(_ctx, getState());
  enterRule(_localctx, 16, KsmParser::RuleTypeRef);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(334);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__8:
      case KsmParser::T__9:
      case KsmParser::IDENT: {
        _localctx = dynamic_cast<TypeRefContext *>(_tracker.createInstance<KsmParser::NamedTypeContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(323);
        dynamic_cast<NamedTypeContext *>(_localctx)->name = _input->LT(1);
        _la = _input->LA(1);
        if (!((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << KsmParser::T__8)
          | (1ULL << KsmParser::T__9)
          | (1ULL << KsmParser::IDENT))) != 0))) {
          dynamic_cast<NamedTypeContext *>(_localctx)->name = _errHandler->recoverInline(this);
        }
        else {
          _errHandler->reportMatch(this);
          consume();
        }
        setState(327);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__11) {
          setState(324);
          dim();
          setState(329);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        break;
      }

      case KsmParser::T__32: {
        _localctx = dynamic_cast<TypeRefContext *>(_tracker.createInstance<KsmParser::SetTypeContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(330);
        match(KsmParser::T__32);
        setState(331);
        match(KsmParser::T__33);
        setState(332);
        dynamic_cast<SetTypeContext *>(_localctx)->elem = _input->LT(1);
        _la = _input->LA(1);
        if (!((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << KsmParser::T__8)
          | (1ULL << KsmParser::T__9)
          | (1ULL << KsmParser::IDENT))) != 0))) {
          dynamic_cast<SetTypeContext *>(_localctx)->elem = _errHandler->recoverInline(this);
        }
        else {
          _errHandler->reportMatch(this);
          consume();
        }
        setState(333);
        match(KsmParser::T__34);
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- DimContext ------------------------------------------------------------------

KsmParser::DimContext::DimContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::DimContext::NUMBER() {
  return getToken(KsmParser::NUMBER, 0);
}


size_t KsmParser::DimContext::getRuleIndex() const {
  return KsmParser::RuleDim;
}


KsmParser::DimContext* KsmParser::dim() {
  DimContext *_localctx = _tracker.createInstance<DimContext>(_ctx, getState());
  enterRule(_localctx, 18, KsmParser::RuleDim);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(336);
    match(KsmParser::T__11);
    setState(338);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::NUMBER) {
      setState(337);
      match(KsmParser::NUMBER);
    }
    setState(340);
    match(KsmParser::T__12);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ParamRangeContext ------------------------------------------------------------------

KsmParser::ParamRangeContext::ParamRangeContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<KsmParser::BoundContext *> KsmParser::ParamRangeContext::bound() {
  return getRuleContexts<KsmParser::BoundContext>();
}

KsmParser::BoundContext* KsmParser::ParamRangeContext::bound(size_t i) {
  return getRuleContext<KsmParser::BoundContext>(i);
}


size_t KsmParser::ParamRangeContext::getRuleIndex() const {
  return KsmParser::RuleParamRange;
}


KsmParser::ParamRangeContext* KsmParser::paramRange() {
  ParamRangeContext *_localctx = _tracker.createInstance<ParamRangeContext>(_ctx, getState());
  enterRule(_localctx, 20, KsmParser::RuleParamRange);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(342);
    match(KsmParser::T__35);
    setState(343);
    dynamic_cast<ParamRangeContext *>(_localctx)->lo = _input->LT(1);
    _la = _input->LA(1);
    if (!(_la == KsmParser::T__11

    || _la == KsmParser::T__16)) {
      dynamic_cast<ParamRangeContext *>(_localctx)->lo = _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
    setState(344);
    dynamic_cast<ParamRangeContext *>(_localctx)->lower = bound();
    setState(345);
    match(KsmParser::T__6);
    setState(346);
    dynamic_cast<ParamRangeContext *>(_localctx)->upper = bound();
    setState(347);
    dynamic_cast<ParamRangeContext *>(_localctx)->hi = _input->LT(1);
    _la = _input->LA(1);
    if (!(_la == KsmParser::T__12

    || _la == KsmParser::T__17)) {
      dynamic_cast<ParamRangeContext *>(_localctx)->hi = _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- BoundContext ------------------------------------------------------------------

KsmParser::BoundContext::BoundContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

KsmParser::NumberContext* KsmParser::BoundContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}


size_t KsmParser::BoundContext::getRuleIndex() const {
  return KsmParser::RuleBound;
}


KsmParser::BoundContext* KsmParser::bound() {
  BoundContext *_localctx = _tracker.createInstance<BoundContext>(_ctx, getState());
  enterRule(_localctx, 22, KsmParser::RuleBound);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(354);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 37, _ctx)) {
    case 1: {
      enterOuterAlt(_localctx, 1);
      setState(349);
      number();
      break;
    }

    case 2: {
      enterOuterAlt(_localctx, 2);
      setState(351);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__36) {
        setState(350);
        dynamic_cast<BoundContext *>(_localctx)->neg = match(KsmParser::T__36);
      }
      setState(353);
      match(KsmParser::T__37);
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RowSumContext ------------------------------------------------------------------

KsmParser::RowSumContext::RowSumContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

KsmParser::NumberContext* KsmParser::RowSumContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}

tree::TerminalNode* KsmParser::RowSumContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}


size_t KsmParser::RowSumContext::getRuleIndex() const {
  return KsmParser::RuleRowSum;
}


KsmParser::RowSumContext* KsmParser::rowSum() {
  RowSumContext *_localctx = _tracker.createInstance<RowSumContext>(_ctx, getState());
  enterRule(_localctx, 24, KsmParser::RuleRowSum);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(356);
    dynamic_cast<RowSumContext *>(_localctx)->kw = match(KsmParser::IDENT);
    setState(357);
    number();
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- MoveSpecContext ------------------------------------------------------------------

KsmParser::MoveSpecContext::MoveSpecContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t KsmParser::MoveSpecContext::getRuleIndex() const {
  return KsmParser::RuleMoveSpec;
}

void KsmParser::MoveSpecContext::copyFrom(MoveSpecContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- MakesSpecContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> KsmParser::MakesSpecContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::MakesSpecContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::MakesSpecContext::MakesSpecContext(MoveSpecContext *ctx) { copyFrom(ctx); }


//----------------- ServesSpecContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> KsmParser::ServesSpecContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::ServesSpecContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::ServesSpecContext::ServesSpecContext(MoveSpecContext *ctx) { copyFrom(ctx); }


KsmParser::MoveSpecContext* KsmParser::moveSpec() {
  MoveSpecContext *_localctx = _tracker.createInstance<MoveSpecContext>(_ctx, getState());
  enterRule(_localctx, 26, KsmParser::RuleMoveSpec);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(374);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__38: {
        _localctx = dynamic_cast<MoveSpecContext *>(_tracker.createInstance<KsmParser::MakesSpecContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(359);
        match(KsmParser::T__38);
        setState(360);
        match(KsmParser::IDENT);
        setState(363);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == KsmParser::T__27) {
          setState(361);
          match(KsmParser::T__27);
          setState(362);
          match(KsmParser::IDENT);
        }
        break;
      }

      case KsmParser::T__39: {
        _localctx = dynamic_cast<MoveSpecContext *>(_tracker.createInstance<KsmParser::ServesSpecContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(365);
        match(KsmParser::T__39);
        setState(366);
        match(KsmParser::IDENT);
        setState(371);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(367);
          match(KsmParser::T__6);
          setState(368);
          match(KsmParser::IDENT);
          setState(373);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ModelSlotContext ------------------------------------------------------------------

KsmParser::ModelSlotContext::ModelSlotContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<tree::TerminalNode *> KsmParser::ModelSlotContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::ModelSlotContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}


size_t KsmParser::ModelSlotContext::getRuleIndex() const {
  return KsmParser::RuleModelSlot;
}


KsmParser::ModelSlotContext* KsmParser::modelSlot() {
  ModelSlotContext *_localctx = _tracker.createInstance<ModelSlotContext>(_ctx, getState());
  enterRule(_localctx, 28, KsmParser::RuleModelSlot);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(376);
    match(KsmParser::IDENT);
    setState(382);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__11) {
      setState(377);
      match(KsmParser::T__11);
      setState(379);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::IDENT) {
        setState(378);
        dynamic_cast<ModelSlotContext *>(_localctx)->index = match(KsmParser::IDENT);
      }
      setState(381);
      match(KsmParser::T__12);
    }
    setState(384);
    dynamic_cast<ModelSlotContext *>(_localctx)->vmode = _input->LT(1);
    _la = _input->LA(1);
    if (!(_la == KsmParser::T__40

    || _la == KsmParser::T__41)) {
      dynamic_cast<ModelSlotContext *>(_localctx)->vmode = _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RuleNameContext ------------------------------------------------------------------

KsmParser::RuleNameContext::RuleNameContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::RuleNameContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}


size_t KsmParser::RuleNameContext::getRuleIndex() const {
  return KsmParser::RuleRuleName;
}


KsmParser::RuleNameContext* KsmParser::ruleName() {
  RuleNameContext *_localctx = _tracker.createInstance<RuleNameContext>(_ctx, getState());
  enterRule(_localctx, 30, KsmParser::RuleRuleName);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(386);
    match(KsmParser::T__42);
    setState(387);
    match(KsmParser::IDENT);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RuleHeadContext ------------------------------------------------------------------

KsmParser::RuleHeadContext::RuleHeadContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

KsmParser::NumberContext* KsmParser::RuleHeadContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}

tree::TerminalNode* KsmParser::RuleHeadContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}


size_t KsmParser::RuleHeadContext::getRuleIndex() const {
  return KsmParser::RuleRuleHead;
}


KsmParser::RuleHeadContext* KsmParser::ruleHead() {
  RuleHeadContext *_localctx = _tracker.createInstance<RuleHeadContext>(_ctx, getState());
  enterRule(_localctx, 32, KsmParser::RuleRuleHead);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(390);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__43) {
      setState(389);
      dynamic_cast<RuleHeadContext *>(_localctx)->hard = match(KsmParser::T__43);
    }
    setState(400);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 44, _ctx)) {
    case 1: {
      setState(392);
      dynamic_cast<RuleHeadContext *>(_localctx)->weightProb = match(KsmParser::T__44);
      setState(393);
      number();
      setState(394);
      match(KsmParser::T__31);
      break;
    }

    case 2: {
      setState(396);
      dynamic_cast<RuleHeadContext *>(_localctx)->weightRaw = match(KsmParser::IDENT);
      setState(397);
      number();
      setState(398);
      match(KsmParser::T__31);
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RuleBodyContext ------------------------------------------------------------------

KsmParser::RuleBodyContext::RuleBodyContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t KsmParser::RuleBodyContext::getRuleIndex() const {
  return KsmParser::RuleRuleBody;
}

void KsmParser::RuleBodyContext::copyFrom(RuleBodyContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- FormulaBodyContext ------------------------------------------------------------------

KsmParser::FormulaContext* KsmParser::FormulaBodyContext::formula() {
  return getRuleContext<KsmParser::FormulaContext>(0);
}

KsmParser::FormulaBodyContext::FormulaBodyContext(RuleBodyContext *ctx) { copyFrom(ctx); }


//----------------- ExactlyOneBodyContext ------------------------------------------------------------------

std::vector<KsmParser::AtomContext *> KsmParser::ExactlyOneBodyContext::atom() {
  return getRuleContexts<KsmParser::AtomContext>();
}

KsmParser::AtomContext* KsmParser::ExactlyOneBodyContext::atom(size_t i) {
  return getRuleContext<KsmParser::AtomContext>(i);
}

KsmParser::ExactlyOneBodyContext::ExactlyOneBodyContext(RuleBodyContext *ctx) { copyFrom(ctx); }


KsmParser::RuleBodyContext* KsmParser::ruleBody() {
  RuleBodyContext *_localctx = _tracker.createInstance<RuleBodyContext>(_ctx, getState());
  enterRule(_localctx, 34, KsmParser::RuleRuleBody);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(413);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__45: {
        _localctx = dynamic_cast<RuleBodyContext *>(_tracker.createInstance<KsmParser::ExactlyOneBodyContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(402);
        match(KsmParser::T__45);
        setState(403);
        match(KsmParser::T__46);
        setState(404);
        match(KsmParser::T__47);
        setState(405);
        atom();
        setState(408); 
        _errHandler->sync(this);
        _la = _input->LA(1);
        do {
          setState(406);
          match(KsmParser::T__6);
          setState(407);
          atom();
          setState(410); 
          _errHandler->sync(this);
          _la = _input->LA(1);
        } while (_la == KsmParser::T__6);
        break;
      }

      case KsmParser::T__16:
      case KsmParser::T__30:
      case KsmParser::T__52:
      case KsmParser::IDENT: {
        _localctx = dynamic_cast<RuleBodyContext *>(_tracker.createInstance<KsmParser::FormulaBodyContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(412);
        formula();
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- FormulaContext ------------------------------------------------------------------

KsmParser::FormulaContext::FormulaContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<KsmParser::ImplicationContext *> KsmParser::FormulaContext::implication() {
  return getRuleContexts<KsmParser::ImplicationContext>();
}

KsmParser::ImplicationContext* KsmParser::FormulaContext::implication(size_t i) {
  return getRuleContext<KsmParser::ImplicationContext>(i);
}


size_t KsmParser::FormulaContext::getRuleIndex() const {
  return KsmParser::RuleFormula;
}


KsmParser::FormulaContext* KsmParser::formula() {
  FormulaContext *_localctx = _tracker.createInstance<FormulaContext>(_ctx, getState());
  enterRule(_localctx, 36, KsmParser::RuleFormula);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(415);
    implication();
    setState(420);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 47, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        setState(416);
        match(KsmParser::T__48);
        setState(417);
        implication(); 
      }
      setState(422);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 47, _ctx);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ImplicationContext ------------------------------------------------------------------

KsmParser::ImplicationContext::ImplicationContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<KsmParser::DisjunctionContext *> KsmParser::ImplicationContext::disjunction() {
  return getRuleContexts<KsmParser::DisjunctionContext>();
}

KsmParser::DisjunctionContext* KsmParser::ImplicationContext::disjunction(size_t i) {
  return getRuleContext<KsmParser::DisjunctionContext>(i);
}


size_t KsmParser::ImplicationContext::getRuleIndex() const {
  return KsmParser::RuleImplication;
}


KsmParser::ImplicationContext* KsmParser::implication() {
  ImplicationContext *_localctx = _tracker.createInstance<ImplicationContext>(_ctx, getState());
  enterRule(_localctx, 38, KsmParser::RuleImplication);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(423);
    disjunction();
    setState(428);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 48, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        setState(424);
        match(KsmParser::T__49);
        setState(425);
        disjunction(); 
      }
      setState(430);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 48, _ctx);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- DisjunctionContext ------------------------------------------------------------------

KsmParser::DisjunctionContext::DisjunctionContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<KsmParser::ConjunctionContext *> KsmParser::DisjunctionContext::conjunction() {
  return getRuleContexts<KsmParser::ConjunctionContext>();
}

KsmParser::ConjunctionContext* KsmParser::DisjunctionContext::conjunction(size_t i) {
  return getRuleContext<KsmParser::ConjunctionContext>(i);
}


size_t KsmParser::DisjunctionContext::getRuleIndex() const {
  return KsmParser::RuleDisjunction;
}


KsmParser::DisjunctionContext* KsmParser::disjunction() {
  DisjunctionContext *_localctx = _tracker.createInstance<DisjunctionContext>(_ctx, getState());
  enterRule(_localctx, 40, KsmParser::RuleDisjunction);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(431);
    conjunction();
    setState(436);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 49, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        setState(432);
        match(KsmParser::T__50);
        setState(433);
        conjunction(); 
      }
      setState(438);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 49, _ctx);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ConjunctionContext ------------------------------------------------------------------

KsmParser::ConjunctionContext::ConjunctionContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<KsmParser::UnaryContext *> KsmParser::ConjunctionContext::unary() {
  return getRuleContexts<KsmParser::UnaryContext>();
}

KsmParser::UnaryContext* KsmParser::ConjunctionContext::unary(size_t i) {
  return getRuleContext<KsmParser::UnaryContext>(i);
}


size_t KsmParser::ConjunctionContext::getRuleIndex() const {
  return KsmParser::RuleConjunction;
}


KsmParser::ConjunctionContext* KsmParser::conjunction() {
  ConjunctionContext *_localctx = _tracker.createInstance<ConjunctionContext>(_ctx, getState());
  enterRule(_localctx, 42, KsmParser::RuleConjunction);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(439);
    unary();
    setState(444);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 50, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        setState(440);
        match(KsmParser::T__51);
        setState(441);
        unary(); 
      }
      setState(446);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 50, _ctx);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- UnaryContext ------------------------------------------------------------------

KsmParser::UnaryContext::UnaryContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t KsmParser::UnaryContext::getRuleIndex() const {
  return KsmParser::RuleUnary;
}

void KsmParser::UnaryContext::copyFrom(UnaryContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- ParenFormulaContext ------------------------------------------------------------------

KsmParser::FormulaContext* KsmParser::ParenFormulaContext::formula() {
  return getRuleContext<KsmParser::FormulaContext>(0);
}

KsmParser::ParenFormulaContext::ParenFormulaContext(UnaryContext *ctx) { copyFrom(ctx); }


//----------------- AtomFormulaContext ------------------------------------------------------------------

KsmParser::AtomContext* KsmParser::AtomFormulaContext::atom() {
  return getRuleContext<KsmParser::AtomContext>(0);
}

KsmParser::AtomFormulaContext::AtomFormulaContext(UnaryContext *ctx) { copyFrom(ctx); }


//----------------- NotFormulaContext ------------------------------------------------------------------

KsmParser::UnaryContext* KsmParser::NotFormulaContext::unary() {
  return getRuleContext<KsmParser::UnaryContext>(0);
}

KsmParser::NotFormulaContext::NotFormulaContext(UnaryContext *ctx) { copyFrom(ctx); }


//----------------- ExistsFormulaContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> KsmParser::ExistsFormulaContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::ExistsFormulaContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::FormulaContext* KsmParser::ExistsFormulaContext::formula() {
  return getRuleContext<KsmParser::FormulaContext>(0);
}

KsmParser::ExistsFormulaContext::ExistsFormulaContext(UnaryContext *ctx) { copyFrom(ctx); }


KsmParser::UnaryContext* KsmParser::unary() {
  UnaryContext *_localctx = _tracker.createInstance<UnaryContext>(_ctx, getState());
  enterRule(_localctx, 44, KsmParser::RuleUnary);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(465);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__30: {
        _localctx = dynamic_cast<UnaryContext *>(_tracker.createInstance<KsmParser::NotFormulaContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(447);
        match(KsmParser::T__30);
        setState(448);
        unary();
        break;
      }

      case KsmParser::T__52: {
        _localctx = dynamic_cast<UnaryContext *>(_tracker.createInstance<KsmParser::ExistsFormulaContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(449);
        match(KsmParser::T__52);
        setState(450);
        match(KsmParser::IDENT);
        setState(455);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(451);
          match(KsmParser::T__6);
          setState(452);
          match(KsmParser::IDENT);
          setState(457);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(458);
        match(KsmParser::T__31);
        setState(459);
        formula();
        break;
      }

      case KsmParser::IDENT: {
        _localctx = dynamic_cast<UnaryContext *>(_tracker.createInstance<KsmParser::AtomFormulaContext>(_localctx));
        enterOuterAlt(_localctx, 3);
        setState(460);
        atom();
        break;
      }

      case KsmParser::T__16: {
        _localctx = dynamic_cast<UnaryContext *>(_tracker.createInstance<KsmParser::ParenFormulaContext>(_localctx));
        enterOuterAlt(_localctx, 4);
        setState(461);
        match(KsmParser::T__16);
        setState(462);
        formula();
        setState(463);
        match(KsmParser::T__17);
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- AtomContext ------------------------------------------------------------------

KsmParser::AtomContext::AtomContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<tree::TerminalNode *> KsmParser::AtomContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::AtomContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}


size_t KsmParser::AtomContext::getRuleIndex() const {
  return KsmParser::RuleAtom;
}


KsmParser::AtomContext* KsmParser::atom() {
  AtomContext *_localctx = _tracker.createInstance<AtomContext>(_ctx, getState());
  enterRule(_localctx, 46, KsmParser::RuleAtom);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(467);
    match(KsmParser::IDENT);
    setState(468);
    match(KsmParser::T__16);
    setState(469);
    match(KsmParser::IDENT);
    setState(474);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == KsmParser::T__6) {
      setState(470);
      match(KsmParser::T__6);
      setState(471);
      match(KsmParser::IDENT);
      setState(476);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(477);
    match(KsmParser::T__17);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ModelVarContext ------------------------------------------------------------------

KsmParser::ModelVarContext::ModelVarContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<tree::TerminalNode *> KsmParser::ModelVarContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::ModelVarContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::TypeRefContext* KsmParser::ModelVarContext::typeRef() {
  return getRuleContext<KsmParser::TypeRefContext>(0);
}


size_t KsmParser::ModelVarContext::getRuleIndex() const {
  return KsmParser::RuleModelVar;
}


KsmParser::ModelVarContext* KsmParser::modelVar() {
  ModelVarContext *_localctx = _tracker.createInstance<ModelVarContext>(_ctx, getState());
  enterRule(_localctx, 48, KsmParser::RuleModelVar);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(496);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 55, _ctx)) {
    case 1: {
      enterOuterAlt(_localctx, 1);
      setState(479);
      match(KsmParser::IDENT);
      setState(480);
      match(KsmParser::T__11);
      setState(482);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::IDENT) {
        setState(481);
        dynamic_cast<ModelVarContext *>(_localctx)->index = match(KsmParser::IDENT);
      }
      setState(484);
      match(KsmParser::T__12);
      setState(485);
      match(KsmParser::T__31);
      setState(486);
      typeRef();
      setState(487);
      dynamic_cast<ModelVarContext *>(_localctx)->vmode = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == KsmParser::T__40

      || _la == KsmParser::T__41)) {
        dynamic_cast<ModelVarContext *>(_localctx)->vmode = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(488);
      match(KsmParser::T__1);
      break;
    }

    case 2: {
      enterOuterAlt(_localctx, 2);
      setState(490);
      match(KsmParser::IDENT);
      setState(491);
      match(KsmParser::T__31);
      setState(492);
      typeRef();
      setState(493);
      dynamic_cast<ModelVarContext *>(_localctx)->vmode = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == KsmParser::T__40

      || _la == KsmParser::T__41)) {
        dynamic_cast<ModelVarContext *>(_localctx)->vmode = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(494);
      match(KsmParser::T__1);
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- PriorFormContext ------------------------------------------------------------------

KsmParser::PriorFormContext::PriorFormContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<tree::TerminalNode *> KsmParser::PriorFormContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::PriorFormContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::CallContext* KsmParser::PriorFormContext::call() {
  return getRuleContext<KsmParser::CallContext>(0);
}

std::vector<KsmParser::ConditionContext *> KsmParser::PriorFormContext::condition() {
  return getRuleContexts<KsmParser::ConditionContext>();
}

KsmParser::ConditionContext* KsmParser::PriorFormContext::condition(size_t i) {
  return getRuleContext<KsmParser::ConditionContext>(i);
}


size_t KsmParser::PriorFormContext::getRuleIndex() const {
  return KsmParser::RulePriorForm;
}


KsmParser::PriorFormContext* KsmParser::priorForm() {
  PriorFormContext *_localctx = _tracker.createInstance<PriorFormContext>(_ctx, getState());
  enterRule(_localctx, 50, KsmParser::RulePriorForm);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(521);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__53: {
        enterOuterAlt(_localctx, 1);
        setState(498);
        match(KsmParser::T__53);
        setState(499);
        match(KsmParser::IDENT);
        setState(504);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(500);
          match(KsmParser::T__6);
          setState(501);
          match(KsmParser::IDENT);
          setState(506);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(516);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == KsmParser::T__54) {
          setState(507);
          match(KsmParser::T__54);
          setState(508);
          condition();
          setState(513);
          _errHandler->sync(this);
          _la = _input->LA(1);
          while (_la == KsmParser::T__55) {
            setState(509);
            match(KsmParser::T__55);
            setState(510);
            condition();
            setState(515);
            _errHandler->sync(this);
            _la = _input->LA(1);
          }
        }
        setState(518);
        match(KsmParser::T__31);
        setState(519);
        call();
        break;
      }

      case KsmParser::IDENT: {
        enterOuterAlt(_localctx, 2);
        setState(520);
        call();
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ConditionContext ------------------------------------------------------------------

KsmParser::ConditionContext::ConditionContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t KsmParser::ConditionContext::getRuleIndex() const {
  return KsmParser::RuleCondition;
}

void KsmParser::ConditionContext::copyFrom(ConditionContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- AtomConditionContext ------------------------------------------------------------------

KsmParser::AtomContext* KsmParser::AtomConditionContext::atom() {
  return getRuleContext<KsmParser::AtomContext>(0);
}

KsmParser::AtomConditionContext::AtomConditionContext(ConditionContext *ctx) { copyFrom(ctx); }


//----------------- ProbConditionContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::ProbConditionContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

KsmParser::AtomContext* KsmParser::ProbConditionContext::atom() {
  return getRuleContext<KsmParser::AtomContext>(0);
}

KsmParser::NumberContext* KsmParser::ProbConditionContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}

KsmParser::ProbConditionContext::ProbConditionContext(ConditionContext *ctx) { copyFrom(ctx); }


KsmParser::ConditionContext* KsmParser::condition() {
  ConditionContext *_localctx = _tracker.createInstance<ConditionContext>(_ctx, getState());
  enterRule(_localctx, 52, KsmParser::RuleCondition);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(534);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 61, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<ConditionContext *>(_tracker.createInstance<KsmParser::ProbConditionContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(523);
      match(KsmParser::IDENT);
      setState(524);
      match(KsmParser::T__16);
      setState(525);
      atom();
      setState(526);
      match(KsmParser::T__17);
      setState(527);
      dynamic_cast<ProbConditionContext *>(_localctx)->op = _input->LT(1);
      _la = _input->LA(1);
      if (!((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__33)
        | (1ULL << KsmParser::T__34)
        | (1ULL << KsmParser::T__56)
        | (1ULL << KsmParser::T__57))) != 0))) {
        dynamic_cast<ProbConditionContext *>(_localctx)->op = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(528);
      number();
      break;
    }

    case 2: {
      _localctx = dynamic_cast<ConditionContext *>(_tracker.createInstance<KsmParser::AtomConditionContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(531);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__30) {
        setState(530);
        dynamic_cast<AtomConditionContext *>(_localctx)->neg = match(KsmParser::T__30);
      }
      setState(533);
      atom();
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- KernelParamsContext ------------------------------------------------------------------

KsmParser::KernelParamsContext::KernelParamsContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<KsmParser::KparamContext *> KsmParser::KernelParamsContext::kparam() {
  return getRuleContexts<KsmParser::KparamContext>();
}

KsmParser::KparamContext* KsmParser::KernelParamsContext::kparam(size_t i) {
  return getRuleContext<KsmParser::KparamContext>(i);
}


size_t KsmParser::KernelParamsContext::getRuleIndex() const {
  return KsmParser::RuleKernelParams;
}


KsmParser::KernelParamsContext* KsmParser::kernelParams() {
  KernelParamsContext *_localctx = _tracker.createInstance<KernelParamsContext>(_ctx, getState());
  enterRule(_localctx, 54, KsmParser::RuleKernelParams);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(536);
    match(KsmParser::T__16);
    setState(537);
    kparam();
    setState(542);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == KsmParser::T__6) {
      setState(538);
      match(KsmParser::T__6);
      setState(539);
      kparam();
      setState(544);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(545);
    match(KsmParser::T__17);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- KparamContext ------------------------------------------------------------------

KsmParser::KparamContext::KparamContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<tree::TerminalNode *> KsmParser::KparamContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::KparamContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}


size_t KsmParser::KparamContext::getRuleIndex() const {
  return KsmParser::RuleKparam;
}


KsmParser::KparamContext* KsmParser::kparam() {
  KparamContext *_localctx = _tracker.createInstance<KparamContext>(_ctx, getState());
  enterRule(_localctx, 56, KsmParser::RuleKparam);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(547);
    match(KsmParser::IDENT);
    setState(548);
    match(KsmParser::T__31);
    setState(549);
    match(KsmParser::IDENT);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ScheduleRowContext ------------------------------------------------------------------

KsmParser::ScheduleRowContext::ScheduleRowContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<KsmParser::ScheduleEntryContext *> KsmParser::ScheduleRowContext::scheduleEntry() {
  return getRuleContexts<KsmParser::ScheduleEntryContext>();
}

KsmParser::ScheduleEntryContext* KsmParser::ScheduleRowContext::scheduleEntry(size_t i) {
  return getRuleContext<KsmParser::ScheduleEntryContext>(i);
}

KsmParser::NumberContext* KsmParser::ScheduleRowContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}

KsmParser::RangeEndContext* KsmParser::ScheduleRowContext::rangeEnd() {
  return getRuleContext<KsmParser::RangeEndContext>(0);
}


size_t KsmParser::ScheduleRowContext::getRuleIndex() const {
  return KsmParser::RuleScheduleRow;
}


KsmParser::ScheduleRowContext* KsmParser::scheduleRow() {
  ScheduleRowContext *_localctx = _tracker.createInstance<ScheduleRowContext>(_ctx, getState());
  enterRule(_localctx, 58, KsmParser::RuleScheduleRow);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(558);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__11) {
      setState(551);
      match(KsmParser::T__11);
      setState(552);
      dynamic_cast<ScheduleRowContext *>(_localctx)->lo = number();
      setState(553);
      match(KsmParser::T__6);
      setState(554);
      dynamic_cast<ScheduleRowContext *>(_localctx)->hi = rangeEnd();
      setState(555);
      match(KsmParser::T__17);
      setState(556);
      match(KsmParser::T__31);
    }
    setState(560);
    match(KsmParser::T__5);
    setState(569);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::IDENT) {
      setState(561);
      scheduleEntry();
      setState(566);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::T__6) {
        setState(562);
        match(KsmParser::T__6);
        setState(563);
        scheduleEntry();
        setState(568);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
    }
    setState(571);
    match(KsmParser::T__7);
    setState(573);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__1) {
      setState(572);
      match(KsmParser::T__1);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RangeEndContext ------------------------------------------------------------------

KsmParser::RangeEndContext::RangeEndContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

KsmParser::NumberContext* KsmParser::RangeEndContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}


size_t KsmParser::RangeEndContext::getRuleIndex() const {
  return KsmParser::RuleRangeEnd;
}


KsmParser::RangeEndContext* KsmParser::rangeEnd() {
  RangeEndContext *_localctx = _tracker.createInstance<RangeEndContext>(_ctx, getState());
  enterRule(_localctx, 60, KsmParser::RuleRangeEnd);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(577);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__36:
      case KsmParser::NUMBER: {
        enterOuterAlt(_localctx, 1);
        setState(575);
        number();
        break;
      }

      case KsmParser::T__37: {
        enterOuterAlt(_localctx, 2);
        setState(576);
        match(KsmParser::T__37);
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ScheduleEntryContext ------------------------------------------------------------------

KsmParser::ScheduleEntryContext::ScheduleEntryContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::ScheduleEntryContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

KsmParser::NumberContext* KsmParser::ScheduleEntryContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}


size_t KsmParser::ScheduleEntryContext::getRuleIndex() const {
  return KsmParser::RuleScheduleEntry;
}


KsmParser::ScheduleEntryContext* KsmParser::scheduleEntry() {
  ScheduleEntryContext *_localctx = _tracker.createInstance<ScheduleEntryContext>(_ctx, getState());
  enterRule(_localctx, 62, KsmParser::RuleScheduleEntry);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(579);
    match(KsmParser::IDENT);
    setState(580);
    match(KsmParser::T__31);
    setState(581);
    number();
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- CallContext ------------------------------------------------------------------

KsmParser::CallContext::CallContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

KsmParser::QualNameContext* KsmParser::CallContext::qualName() {
  return getRuleContext<KsmParser::QualNameContext>(0);
}

std::vector<KsmParser::ArgContext *> KsmParser::CallContext::arg() {
  return getRuleContexts<KsmParser::ArgContext>();
}

KsmParser::ArgContext* KsmParser::CallContext::arg(size_t i) {
  return getRuleContext<KsmParser::ArgContext>(i);
}


size_t KsmParser::CallContext::getRuleIndex() const {
  return KsmParser::RuleCall;
}


KsmParser::CallContext* KsmParser::call() {
  CallContext *_localctx = _tracker.createInstance<CallContext>(_ctx, getState());
  enterRule(_localctx, 64, KsmParser::RuleCall);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(583);
    qualName();
    setState(596);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__16) {
      setState(584);
      match(KsmParser::T__16);
      setState(593);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__5)
        | (1ULL << KsmParser::T__11)
        | (1ULL << KsmParser::T__36)
        | (1ULL << KsmParser::T__37)
        | (1ULL << KsmParser::T__58)
        | (1ULL << KsmParser::T__59)
        | (1ULL << KsmParser::NUMBER)
        | (1ULL << KsmParser::IDENT)
        | (1ULL << KsmParser::STRING))) != 0)) {
        setState(585);
        arg();
        setState(590);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(586);
          match(KsmParser::T__6);
          setState(587);
          arg();
          setState(592);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(595);
      match(KsmParser::T__17);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ArgContext ------------------------------------------------------------------

KsmParser::ArgContext::ArgContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

KsmParser::ExprContext* KsmParser::ArgContext::expr() {
  return getRuleContext<KsmParser::ExprContext>(0);
}

tree::TerminalNode* KsmParser::ArgContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}


size_t KsmParser::ArgContext::getRuleIndex() const {
  return KsmParser::RuleArg;
}


KsmParser::ArgContext* KsmParser::arg() {
  ArgContext *_localctx = _tracker.createInstance<ArgContext>(_ctx, getState());
  enterRule(_localctx, 66, KsmParser::RuleArg);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(600);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 71, _ctx)) {
    case 1: {
      setState(598);
      match(KsmParser::IDENT);
      setState(599);
      match(KsmParser::T__4);
      break;
    }

    }
    setState(602);
    expr();
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ExprContext ------------------------------------------------------------------

KsmParser::ExprContext::ExprContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t KsmParser::ExprContext::getRuleIndex() const {
  return KsmParser::RuleExpr;
}

void KsmParser::ExprContext::copyFrom(ExprContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- StringExprContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::StringExprContext::STRING() {
  return getToken(KsmParser::STRING, 0);
}

KsmParser::StringExprContext::StringExprContext(ExprContext *ctx) { copyFrom(ctx); }


//----------------- IndexExprContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> KsmParser::IndexExprContext::IDENT() {
  return getTokens(KsmParser::IDENT);
}

tree::TerminalNode* KsmParser::IndexExprContext::IDENT(size_t i) {
  return getToken(KsmParser::IDENT, i);
}

KsmParser::IndexExprContext::IndexExprContext(ExprContext *ctx) { copyFrom(ctx); }


//----------------- NumberExprContext ------------------------------------------------------------------

KsmParser::NumberContext* KsmParser::NumberExprContext::number() {
  return getRuleContext<KsmParser::NumberContext>(0);
}

KsmParser::NumberExprContext::NumberExprContext(ExprContext *ctx) { copyFrom(ctx); }


//----------------- InfExprContext ------------------------------------------------------------------

KsmParser::InfExprContext::InfExprContext(ExprContext *ctx) { copyFrom(ctx); }


//----------------- BoolExprContext ------------------------------------------------------------------

KsmParser::BoolExprContext::BoolExprContext(ExprContext *ctx) { copyFrom(ctx); }


//----------------- CallExprContext ------------------------------------------------------------------

KsmParser::QualNameContext* KsmParser::CallExprContext::qualName() {
  return getRuleContext<KsmParser::QualNameContext>(0);
}

std::vector<KsmParser::ArgContext *> KsmParser::CallExprContext::arg() {
  return getRuleContexts<KsmParser::ArgContext>();
}

KsmParser::ArgContext* KsmParser::CallExprContext::arg(size_t i) {
  return getRuleContext<KsmParser::ArgContext>(i);
}

KsmParser::CallExprContext::CallExprContext(ExprContext *ctx) { copyFrom(ctx); }


//----------------- ListExprContext ------------------------------------------------------------------

std::vector<KsmParser::ExprContext *> KsmParser::ListExprContext::expr() {
  return getRuleContexts<KsmParser::ExprContext>();
}

KsmParser::ExprContext* KsmParser::ListExprContext::expr(size_t i) {
  return getRuleContext<KsmParser::ExprContext>(i);
}

KsmParser::ListExprContext::ListExprContext(ExprContext *ctx) { copyFrom(ctx); }


//----------------- NameExprContext ------------------------------------------------------------------

tree::TerminalNode* KsmParser::NameExprContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}

KsmParser::NameExprContext::NameExprContext(ExprContext *ctx) { copyFrom(ctx); }


//----------------- SetExprContext ------------------------------------------------------------------

std::vector<KsmParser::ExprContext *> KsmParser::SetExprContext::expr() {
  return getRuleContexts<KsmParser::ExprContext>();
}

KsmParser::ExprContext* KsmParser::SetExprContext::expr(size_t i) {
  return getRuleContext<KsmParser::ExprContext>(i);
}

KsmParser::SetExprContext::SetExprContext(ExprContext *ctx) { copyFrom(ctx); }


KsmParser::ExprContext* KsmParser::expr() {
  ExprContext *_localctx = _tracker.createInstance<ExprContext>(_ctx, getState());
  enterRule(_localctx, 68, KsmParser::RuleExpr);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(651);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 78, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::NumberExprContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(604);
      number();
      break;
    }

    case 2: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::StringExprContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(605);
      match(KsmParser::STRING);
      break;
    }

    case 3: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::BoolExprContext>(_localctx));
      enterOuterAlt(_localctx, 3);
      setState(606);
      _la = _input->LA(1);
      if (!(_la == KsmParser::T__58

      || _la == KsmParser::T__59)) {
      _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      break;
    }

    case 4: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::InfExprContext>(_localctx));
      enterOuterAlt(_localctx, 4);
      setState(607);
      match(KsmParser::T__37);
      break;
    }

    case 5: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::IndexExprContext>(_localctx));
      enterOuterAlt(_localctx, 5);
      setState(608);
      match(KsmParser::IDENT);
      setState(609);
      match(KsmParser::T__11);
      setState(610);
      match(KsmParser::IDENT);
      setState(611);
      match(KsmParser::T__12);
      break;
    }

    case 6: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::CallExprContext>(_localctx));
      enterOuterAlt(_localctx, 6);
      setState(612);
      qualName();
      setState(613);
      match(KsmParser::T__16);
      setState(622);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__5)
        | (1ULL << KsmParser::T__11)
        | (1ULL << KsmParser::T__36)
        | (1ULL << KsmParser::T__37)
        | (1ULL << KsmParser::T__58)
        | (1ULL << KsmParser::T__59)
        | (1ULL << KsmParser::NUMBER)
        | (1ULL << KsmParser::IDENT)
        | (1ULL << KsmParser::STRING))) != 0)) {
        setState(614);
        arg();
        setState(619);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(615);
          match(KsmParser::T__6);
          setState(616);
          arg();
          setState(621);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(624);
      match(KsmParser::T__17);
      break;
    }

    case 7: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::NameExprContext>(_localctx));
      enterOuterAlt(_localctx, 7);
      setState(626);
      match(KsmParser::IDENT);
      break;
    }

    case 8: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::ListExprContext>(_localctx));
      enterOuterAlt(_localctx, 8);
      setState(627);
      match(KsmParser::T__11);
      setState(636);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__5)
        | (1ULL << KsmParser::T__11)
        | (1ULL << KsmParser::T__36)
        | (1ULL << KsmParser::T__37)
        | (1ULL << KsmParser::T__58)
        | (1ULL << KsmParser::T__59)
        | (1ULL << KsmParser::NUMBER)
        | (1ULL << KsmParser::IDENT)
        | (1ULL << KsmParser::STRING))) != 0)) {
        setState(628);
        expr();
        setState(633);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(629);
          match(KsmParser::T__6);
          setState(630);
          expr();
          setState(635);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(638);
      match(KsmParser::T__12);
      break;
    }

    case 9: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::SetExprContext>(_localctx));
      enterOuterAlt(_localctx, 9);
      setState(639);
      match(KsmParser::T__5);
      setState(648);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__5)
        | (1ULL << KsmParser::T__11)
        | (1ULL << KsmParser::T__36)
        | (1ULL << KsmParser::T__37)
        | (1ULL << KsmParser::T__58)
        | (1ULL << KsmParser::T__59)
        | (1ULL << KsmParser::NUMBER)
        | (1ULL << KsmParser::IDENT)
        | (1ULL << KsmParser::STRING))) != 0)) {
        setState(640);
        expr();
        setState(645);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(641);
          match(KsmParser::T__6);
          setState(642);
          expr();
          setState(647);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(650);
      match(KsmParser::T__7);
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- NumberContext ------------------------------------------------------------------

KsmParser::NumberContext::NumberContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* KsmParser::NumberContext::NUMBER() {
  return getToken(KsmParser::NUMBER, 0);
}

tree::TerminalNode* KsmParser::NumberContext::IDENT() {
  return getToken(KsmParser::IDENT, 0);
}


size_t KsmParser::NumberContext::getRuleIndex() const {
  return KsmParser::RuleNumber;
}


KsmParser::NumberContext* KsmParser::number() {
  NumberContext *_localctx = _tracker.createInstance<NumberContext>(_ctx, getState());
  enterRule(_localctx, 70, KsmParser::RuleNumber);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(654);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__36) {
      setState(653);
      match(KsmParser::T__36);
    }
    setState(656);
    match(KsmParser::NUMBER);
    setState(658);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::IDENT) {
      setState(657);
      dynamic_cast<NumberContext *>(_localctx)->unit = match(KsmParser::IDENT);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

// Static vars and initialization.
std::vector<dfa::DFA> KsmParser::_decisionToDFA;
atn::PredictionContextCache KsmParser::_sharedContextCache;

// We own the ATN which in turn owns the ATN states.
atn::ATN KsmParser::_atn;
std::vector<uint16_t> KsmParser::_serializedATN;

std::vector<std::string> KsmParser::_ruleNames = {
  "file", "item", "externKind", "predSig", "predArg", "unitDef", "qualName", 
  "param", "typeRef", "dim", "paramRange", "bound", "rowSum", "moveSpec", 
  "modelSlot", "ruleName", "ruleHead", "ruleBody", "formula", "implication", 
  "disjunction", "conjunction", "unary", "atom", "modelVar", "priorForm", 
  "condition", "kernelParams", "kparam", "scheduleRow", "rangeEnd", "scheduleEntry", 
  "call", "arg", "expr", "number"
};

std::vector<std::string> KsmParser::_literalNames = {
  "", "'domain'", "';'", "'include'", "'type'", "'='", "'{'", "','", "'}'", 
  "'evidence'", "'query'", "'quantity'", "'['", "']'", "'value'", "'extern'", 
  "'model'", "'('", "')'", "'->'", "'reads'", "'.'", "'extract'", "'prior'", 
  "'likelihood'", "'output'", "'kernel'", "'pair'", "'/'", "'reverse'", 
  "'schedule'", "'!'", "':'", "'set'", "'<'", "'>'", "'in'", "'-'", "'inf'", 
  "'makes'", "'serves'", "'fixed'", "'sampled'", "'@'", "'hard'", "'prob'", 
  "'exactly'", "'one'", "'of'", "'<=>'", "'=>'", "'v'", "'^'", "'exists'", 
  "'for'", "'where'", "'and'", "'>='", "'<='", "'true'", "'false'"
};

std::vector<std::string> KsmParser::_symbolicNames = {
  "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", 
  "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", 
  "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", 
  "", "", "", "", "", "", "", "NUMBER", "IDENT", "STRING", "LINE_COMMENT", 
  "BLOCK_COMMENT", "WS", "ERRCHAR"
};

dfa::Vocabulary KsmParser::_vocabulary(_literalNames, _symbolicNames);

std::vector<std::string> KsmParser::_tokenNames;

KsmParser::Initializer::Initializer() {
	for (size_t i = 0; i < _symbolicNames.size(); ++i) {
		std::string name = _vocabulary.getLiteralName(i);
		if (name.empty()) {
			name = _vocabulary.getSymbolicName(i);
		}

		if (name.empty()) {
			_tokenNames.push_back("<INVALID>");
		} else {
      _tokenNames.push_back(name);
    }
	}

  _serializedATN = {
    0x3, 0x608b, 0xa72a, 0x8133, 0xb9ed, 0x417c, 0x3be7, 0x7786, 0x5964, 
    0x3, 0x45, 0x297, 0x4, 0x2, 0x9, 0x2, 0x4, 0x3, 0x9, 0x3, 0x4, 0x4, 
    0x9, 0x4, 0x4, 0x5, 0x9, 0x5, 0x4, 0x6, 0x9, 0x6, 0x4, 0x7, 0x9, 0x7, 
    0x4, 0x8, 0x9, 0x8, 0x4, 0x9, 0x9, 0x9, 0x4, 0xa, 0x9, 0xa, 0x4, 0xb, 
    0x9, 0xb, 0x4, 0xc, 0x9, 0xc, 0x4, 0xd, 0x9, 0xd, 0x4, 0xe, 0x9, 0xe, 
    0x4, 0xf, 0x9, 0xf, 0x4, 0x10, 0x9, 0x10, 0x4, 0x11, 0x9, 0x11, 0x4, 
    0x12, 0x9, 0x12, 0x4, 0x13, 0x9, 0x13, 0x4, 0x14, 0x9, 0x14, 0x4, 0x15, 
    0x9, 0x15, 0x4, 0x16, 0x9, 0x16, 0x4, 0x17, 0x9, 0x17, 0x4, 0x18, 0x9, 
    0x18, 0x4, 0x19, 0x9, 0x19, 0x4, 0x1a, 0x9, 0x1a, 0x4, 0x1b, 0x9, 0x1b, 
    0x4, 0x1c, 0x9, 0x1c, 0x4, 0x1d, 0x9, 0x1d, 0x4, 0x1e, 0x9, 0x1e, 0x4, 
    0x1f, 0x9, 0x1f, 0x4, 0x20, 0x9, 0x20, 0x4, 0x21, 0x9, 0x21, 0x4, 0x22, 
    0x9, 0x22, 0x4, 0x23, 0x9, 0x23, 0x4, 0x24, 0x9, 0x24, 0x4, 0x25, 0x9, 
    0x25, 0x3, 0x2, 0x7, 0x2, 0x4c, 0xa, 0x2, 0xc, 0x2, 0xe, 0x2, 0x4f, 
    0xb, 0x2, 0x3, 0x2, 0x3, 0x2, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0x60, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0x63, 
    0xb, 0x3, 0x3, 0x3, 0x5, 0x3, 0x66, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0x6d, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 
    0x70, 0xb, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0x7a, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 
    0x7d, 0xb, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0x81, 0xa, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0x88, 0xa, 0x3, 0xc, 
    0x3, 0xe, 0x3, 0x8b, 0xb, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0x94, 0xa, 0x3, 0xc, 0x3, 0xe, 
    0x3, 0x97, 0xb, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0xa3, 0xa, 
    0x3, 0xc, 0x3, 0xe, 0x3, 0xa6, 0xb, 0x3, 0x5, 0x3, 0xa8, 0xa, 0x3, 0x3, 
    0x3, 0x5, 0x3, 0xab, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0xaf, 0xa, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0xb3, 0xa, 0x3, 0x3, 0x3, 0x5, 0x3, 
    0xb6, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0xbb, 0xa, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x7, 0x3, 0xc5, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0xc8, 0xb, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0xe3, 0xa, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0xe9, 0xa, 0x3, 0xc, 0x3, 
    0xe, 0x3, 0xec, 0xb, 0x3, 0x5, 0x3, 0xee, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0xf4, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 
    0x3, 0xf8, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 
    0xfe, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0x101, 0xb, 0x3, 0x5, 0x3, 0x103, 
    0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0x109, 0xa, 
    0x3, 0xc, 0x3, 0xe, 0x3, 0x10c, 0xb, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x7, 0x3, 0x111, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0x114, 0xb, 0x3, 0x5, 
    0x3, 0x116, 0xa, 0x3, 0x3, 0x3, 0x5, 0x3, 0x119, 0xa, 0x3, 0x3, 0x4, 
    0x3, 0x4, 0x3, 0x5, 0x3, 0x5, 0x3, 0x5, 0x3, 0x5, 0x3, 0x5, 0x7, 0x5, 
    0x122, 0xa, 0x5, 0xc, 0x5, 0xe, 0x5, 0x125, 0xb, 0x5, 0x3, 0x5, 0x3, 
    0x5, 0x3, 0x6, 0x3, 0x6, 0x5, 0x6, 0x12b, 0xa, 0x6, 0x3, 0x7, 0x3, 0x7, 
    0x3, 0x7, 0x3, 0x7, 0x3, 0x8, 0x3, 0x8, 0x3, 0x8, 0x7, 0x8, 0x134, 0xa, 
    0x8, 0xc, 0x8, 0xe, 0x8, 0x137, 0xb, 0x8, 0x3, 0x9, 0x3, 0x9, 0x3, 0x9, 
    0x3, 0x9, 0x5, 0x9, 0x13d, 0xa, 0x9, 0x3, 0x9, 0x5, 0x9, 0x140, 0xa, 
    0x9, 0x3, 0x9, 0x3, 0x9, 0x5, 0x9, 0x144, 0xa, 0x9, 0x3, 0xa, 0x3, 0xa, 
    0x7, 0xa, 0x148, 0xa, 0xa, 0xc, 0xa, 0xe, 0xa, 0x14b, 0xb, 0xa, 0x3, 
    0xa, 0x3, 0xa, 0x3, 0xa, 0x3, 0xa, 0x5, 0xa, 0x151, 0xa, 0xa, 0x3, 0xb, 
    0x3, 0xb, 0x5, 0xb, 0x155, 0xa, 0xb, 0x3, 0xb, 0x3, 0xb, 0x3, 0xc, 0x3, 
    0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xd, 0x3, 
    0xd, 0x5, 0xd, 0x162, 0xa, 0xd, 0x3, 0xd, 0x5, 0xd, 0x165, 0xa, 0xd, 
    0x3, 0xe, 0x3, 0xe, 0x3, 0xe, 0x3, 0xf, 0x3, 0xf, 0x3, 0xf, 0x3, 0xf, 
    0x5, 0xf, 0x16e, 0xa, 0xf, 0x3, 0xf, 0x3, 0xf, 0x3, 0xf, 0x3, 0xf, 0x7, 
    0xf, 0x174, 0xa, 0xf, 0xc, 0xf, 0xe, 0xf, 0x177, 0xb, 0xf, 0x5, 0xf, 
    0x179, 0xa, 0xf, 0x3, 0x10, 0x3, 0x10, 0x3, 0x10, 0x5, 0x10, 0x17e, 
    0xa, 0x10, 0x3, 0x10, 0x5, 0x10, 0x181, 0xa, 0x10, 0x3, 0x10, 0x3, 0x10, 
    0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x3, 0x12, 0x5, 0x12, 0x189, 0xa, 0x12, 
    0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 
    0x12, 0x3, 0x12, 0x5, 0x12, 0x193, 0xa, 0x12, 0x3, 0x13, 0x3, 0x13, 
    0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x6, 0x13, 0x19b, 0xa, 0x13, 
    0xd, 0x13, 0xe, 0x13, 0x19c, 0x3, 0x13, 0x5, 0x13, 0x1a0, 0xa, 0x13, 
    0x3, 0x14, 0x3, 0x14, 0x3, 0x14, 0x7, 0x14, 0x1a5, 0xa, 0x14, 0xc, 0x14, 
    0xe, 0x14, 0x1a8, 0xb, 0x14, 0x3, 0x15, 0x3, 0x15, 0x3, 0x15, 0x7, 0x15, 
    0x1ad, 0xa, 0x15, 0xc, 0x15, 0xe, 0x15, 0x1b0, 0xb, 0x15, 0x3, 0x16, 
    0x3, 0x16, 0x3, 0x16, 0x7, 0x16, 0x1b5, 0xa, 0x16, 0xc, 0x16, 0xe, 0x16, 
    0x1b8, 0xb, 0x16, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x7, 0x17, 0x1bd, 
    0xa, 0x17, 0xc, 0x17, 0xe, 0x17, 0x1c0, 0xb, 0x17, 0x3, 0x18, 0x3, 0x18, 
    0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x7, 0x18, 0x1c8, 0xa, 0x18, 
    0xc, 0x18, 0xe, 0x18, 0x1cb, 0xb, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 
    0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x5, 0x18, 0x1d4, 0xa, 0x18, 
    0x3, 0x19, 0x3, 0x19, 0x3, 0x19, 0x3, 0x19, 0x3, 0x19, 0x7, 0x19, 0x1db, 
    0xa, 0x19, 0xc, 0x19, 0xe, 0x19, 0x1de, 0xb, 0x19, 0x3, 0x19, 0x3, 0x19, 
    0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x5, 0x1a, 0x1e5, 0xa, 0x1a, 0x3, 0x1a, 
    0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x3, 
    0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x5, 0x1a, 0x1f3, 
    0xa, 0x1a, 0x3, 0x1b, 0x3, 0x1b, 0x3, 0x1b, 0x3, 0x1b, 0x7, 0x1b, 0x1f9, 
    0xa, 0x1b, 0xc, 0x1b, 0xe, 0x1b, 0x1fc, 0xb, 0x1b, 0x3, 0x1b, 0x3, 0x1b, 
    0x3, 0x1b, 0x3, 0x1b, 0x7, 0x1b, 0x202, 0xa, 0x1b, 0xc, 0x1b, 0xe, 0x1b, 
    0x205, 0xb, 0x1b, 0x5, 0x1b, 0x207, 0xa, 0x1b, 0x3, 0x1b, 0x3, 0x1b, 
    0x3, 0x1b, 0x5, 0x1b, 0x20c, 0xa, 0x1b, 0x3, 0x1c, 0x3, 0x1c, 0x3, 0x1c, 
    0x3, 0x1c, 0x3, 0x1c, 0x3, 0x1c, 0x3, 0x1c, 0x3, 0x1c, 0x5, 0x1c, 0x216, 
    0xa, 0x1c, 0x3, 0x1c, 0x5, 0x1c, 0x219, 0xa, 0x1c, 0x3, 0x1d, 0x3, 0x1d, 
    0x3, 0x1d, 0x3, 0x1d, 0x7, 0x1d, 0x21f, 0xa, 0x1d, 0xc, 0x1d, 0xe, 0x1d, 
    0x222, 0xb, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1e, 0x3, 0x1e, 0x3, 0x1e, 
    0x3, 0x1e, 0x3, 0x1f, 0x3, 0x1f, 0x3, 0x1f, 0x3, 0x1f, 0x3, 0x1f, 0x3, 
    0x1f, 0x3, 0x1f, 0x5, 0x1f, 0x231, 0xa, 0x1f, 0x3, 0x1f, 0x3, 0x1f, 
    0x3, 0x1f, 0x3, 0x1f, 0x7, 0x1f, 0x237, 0xa, 0x1f, 0xc, 0x1f, 0xe, 0x1f, 
    0x23a, 0xb, 0x1f, 0x5, 0x1f, 0x23c, 0xa, 0x1f, 0x3, 0x1f, 0x3, 0x1f, 
    0x5, 0x1f, 0x240, 0xa, 0x1f, 0x3, 0x20, 0x3, 0x20, 0x5, 0x20, 0x244, 
    0xa, 0x20, 0x3, 0x21, 0x3, 0x21, 0x3, 0x21, 0x3, 0x21, 0x3, 0x22, 0x3, 
    0x22, 0x3, 0x22, 0x3, 0x22, 0x3, 0x22, 0x7, 0x22, 0x24f, 0xa, 0x22, 
    0xc, 0x22, 0xe, 0x22, 0x252, 0xb, 0x22, 0x5, 0x22, 0x254, 0xa, 0x22, 
    0x3, 0x22, 0x5, 0x22, 0x257, 0xa, 0x22, 0x3, 0x23, 0x3, 0x23, 0x5, 0x23, 
    0x25b, 0xa, 0x23, 0x3, 0x23, 0x3, 0x23, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 
    0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 
    0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x7, 0x24, 0x26c, 0xa, 0x24, 
    0xc, 0x24, 0xe, 0x24, 0x26f, 0xb, 0x24, 0x5, 0x24, 0x271, 0xa, 0x24, 
    0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 
    0x24, 0x7, 0x24, 0x27a, 0xa, 0x24, 0xc, 0x24, 0xe, 0x24, 0x27d, 0xb, 
    0x24, 0x5, 0x24, 0x27f, 0xa, 0x24, 0x3, 0x24, 0x3, 0x24, 0x3, 0x24, 
    0x3, 0x24, 0x3, 0x24, 0x7, 0x24, 0x286, 0xa, 0x24, 0xc, 0x24, 0xe, 0x24, 
    0x289, 0xb, 0x24, 0x5, 0x24, 0x28b, 0xa, 0x24, 0x3, 0x24, 0x5, 0x24, 
    0x28e, 0xa, 0x24, 0x3, 0x25, 0x5, 0x25, 0x291, 0xa, 0x25, 0x3, 0x25, 
    0x3, 0x25, 0x5, 0x25, 0x295, 0xa, 0x25, 0x3, 0x25, 0x2, 0x2, 0x26, 0x2, 
    0x4, 0x6, 0x8, 0xa, 0xc, 0xe, 0x10, 0x12, 0x14, 0x16, 0x18, 0x1a, 0x1c, 
    0x1e, 0x20, 0x22, 0x24, 0x26, 0x28, 0x2a, 0x2c, 0x2e, 0x30, 0x32, 0x34, 
    0x36, 0x38, 0x3a, 0x3c, 0x3e, 0x40, 0x42, 0x44, 0x46, 0x48, 0x2, 0xa, 
    0x3, 0x2, 0xb, 0xc, 0x4, 0x2, 0x19, 0x1c, 0x40, 0x40, 0x4, 0x2, 0xb, 
    0xc, 0x40, 0x40, 0x4, 0x2, 0xe, 0xe, 0x13, 0x13, 0x4, 0x2, 0xf, 0xf, 
    0x14, 0x14, 0x3, 0x2, 0x2b, 0x2c, 0x4, 0x2, 0x24, 0x25, 0x3b, 0x3c, 
    0x3, 0x2, 0x3d, 0x3e, 0x2, 0x2dc, 0x2, 0x4d, 0x3, 0x2, 0x2, 0x2, 0x4, 
    0x118, 0x3, 0x2, 0x2, 0x2, 0x6, 0x11a, 0x3, 0x2, 0x2, 0x2, 0x8, 0x11c, 
    0x3, 0x2, 0x2, 0x2, 0xa, 0x128, 0x3, 0x2, 0x2, 0x2, 0xc, 0x12c, 0x3, 
    0x2, 0x2, 0x2, 0xe, 0x130, 0x3, 0x2, 0x2, 0x2, 0x10, 0x138, 0x3, 0x2, 
    0x2, 0x2, 0x12, 0x150, 0x3, 0x2, 0x2, 0x2, 0x14, 0x152, 0x3, 0x2, 0x2, 
    0x2, 0x16, 0x158, 0x3, 0x2, 0x2, 0x2, 0x18, 0x164, 0x3, 0x2, 0x2, 0x2, 
    0x1a, 0x166, 0x3, 0x2, 0x2, 0x2, 0x1c, 0x178, 0x3, 0x2, 0x2, 0x2, 0x1e, 
    0x17a, 0x3, 0x2, 0x2, 0x2, 0x20, 0x184, 0x3, 0x2, 0x2, 0x2, 0x22, 0x188, 
    0x3, 0x2, 0x2, 0x2, 0x24, 0x19f, 0x3, 0x2, 0x2, 0x2, 0x26, 0x1a1, 0x3, 
    0x2, 0x2, 0x2, 0x28, 0x1a9, 0x3, 0x2, 0x2, 0x2, 0x2a, 0x1b1, 0x3, 0x2, 
    0x2, 0x2, 0x2c, 0x1b9, 0x3, 0x2, 0x2, 0x2, 0x2e, 0x1d3, 0x3, 0x2, 0x2, 
    0x2, 0x30, 0x1d5, 0x3, 0x2, 0x2, 0x2, 0x32, 0x1f2, 0x3, 0x2, 0x2, 0x2, 
    0x34, 0x20b, 0x3, 0x2, 0x2, 0x2, 0x36, 0x218, 0x3, 0x2, 0x2, 0x2, 0x38, 
    0x21a, 0x3, 0x2, 0x2, 0x2, 0x3a, 0x225, 0x3, 0x2, 0x2, 0x2, 0x3c, 0x230, 
    0x3, 0x2, 0x2, 0x2, 0x3e, 0x243, 0x3, 0x2, 0x2, 0x2, 0x40, 0x245, 0x3, 
    0x2, 0x2, 0x2, 0x42, 0x249, 0x3, 0x2, 0x2, 0x2, 0x44, 0x25a, 0x3, 0x2, 
    0x2, 0x2, 0x46, 0x28d, 0x3, 0x2, 0x2, 0x2, 0x48, 0x290, 0x3, 0x2, 0x2, 
    0x2, 0x4a, 0x4c, 0x5, 0x4, 0x3, 0x2, 0x4b, 0x4a, 0x3, 0x2, 0x2, 0x2, 
    0x4c, 0x4f, 0x3, 0x2, 0x2, 0x2, 0x4d, 0x4b, 0x3, 0x2, 0x2, 0x2, 0x4d, 
    0x4e, 0x3, 0x2, 0x2, 0x2, 0x4e, 0x50, 0x3, 0x2, 0x2, 0x2, 0x4f, 0x4d, 
    0x3, 0x2, 0x2, 0x2, 0x50, 0x51, 0x7, 0x2, 0x2, 0x3, 0x51, 0x3, 0x3, 
    0x2, 0x2, 0x2, 0x52, 0x53, 0x7, 0x3, 0x2, 0x2, 0x53, 0x54, 0x7, 0x40, 
    0x2, 0x2, 0x54, 0x119, 0x7, 0x4, 0x2, 0x2, 0x55, 0x56, 0x7, 0x5, 0x2, 
    0x2, 0x56, 0x57, 0x7, 0x41, 0x2, 0x2, 0x57, 0x119, 0x7, 0x4, 0x2, 0x2, 
    0x58, 0x59, 0x7, 0x6, 0x2, 0x2, 0x59, 0x65, 0x7, 0x40, 0x2, 0x2, 0x5a, 
    0x5b, 0x7, 0x7, 0x2, 0x2, 0x5b, 0x5c, 0x7, 0x8, 0x2, 0x2, 0x5c, 0x61, 
    0x7, 0x40, 0x2, 0x2, 0x5d, 0x5e, 0x7, 0x9, 0x2, 0x2, 0x5e, 0x60, 0x7, 
    0x40, 0x2, 0x2, 0x5f, 0x5d, 0x3, 0x2, 0x2, 0x2, 0x60, 0x63, 0x3, 0x2, 
    0x2, 0x2, 0x61, 0x5f, 0x3, 0x2, 0x2, 0x2, 0x61, 0x62, 0x3, 0x2, 0x2, 
    0x2, 0x62, 0x64, 0x3, 0x2, 0x2, 0x2, 0x63, 0x61, 0x3, 0x2, 0x2, 0x2, 
    0x64, 0x66, 0x7, 0xa, 0x2, 0x2, 0x65, 0x5a, 0x3, 0x2, 0x2, 0x2, 0x65, 
    0x66, 0x3, 0x2, 0x2, 0x2, 0x66, 0x67, 0x3, 0x2, 0x2, 0x2, 0x67, 0x119, 
    0x7, 0x4, 0x2, 0x2, 0x68, 0x69, 0x9, 0x2, 0x2, 0x2, 0x69, 0x6e, 0x5, 
    0x8, 0x5, 0x2, 0x6a, 0x6b, 0x7, 0x9, 0x2, 0x2, 0x6b, 0x6d, 0x5, 0x8, 
    0x5, 0x2, 0x6c, 0x6a, 0x3, 0x2, 0x2, 0x2, 0x6d, 0x70, 0x3, 0x2, 0x2, 
    0x2, 0x6e, 0x6c, 0x3, 0x2, 0x2, 0x2, 0x6e, 0x6f, 0x3, 0x2, 0x2, 0x2, 
    0x6f, 0x71, 0x3, 0x2, 0x2, 0x2, 0x70, 0x6e, 0x3, 0x2, 0x2, 0x2, 0x71, 
    0x72, 0x7, 0x4, 0x2, 0x2, 0x72, 0x119, 0x3, 0x2, 0x2, 0x2, 0x73, 0x74, 
    0x7, 0xd, 0x2, 0x2, 0x74, 0x80, 0x7, 0x40, 0x2, 0x2, 0x75, 0x76, 0x7, 
    0xe, 0x2, 0x2, 0x76, 0x7b, 0x5, 0xc, 0x7, 0x2, 0x77, 0x78, 0x7, 0x9, 
    0x2, 0x2, 0x78, 0x7a, 0x5, 0xc, 0x7, 0x2, 0x79, 0x77, 0x3, 0x2, 0x2, 
    0x2, 0x7a, 0x7d, 0x3, 0x2, 0x2, 0x2, 0x7b, 0x79, 0x3, 0x2, 0x2, 0x2, 
    0x7b, 0x7c, 0x3, 0x2, 0x2, 0x2, 0x7c, 0x7e, 0x3, 0x2, 0x2, 0x2, 0x7d, 
    0x7b, 0x3, 0x2, 0x2, 0x2, 0x7e, 0x7f, 0x7, 0xf, 0x2, 0x2, 0x7f, 0x81, 
    0x3, 0x2, 0x2, 0x2, 0x80, 0x75, 0x3, 0x2, 0x2, 0x2, 0x80, 0x81, 0x3, 
    0x2, 0x2, 0x2, 0x81, 0x82, 0x3, 0x2, 0x2, 0x2, 0x82, 0x119, 0x7, 0x4, 
    0x2, 0x2, 0x83, 0x84, 0x7, 0x10, 0x2, 0x2, 0x84, 0x89, 0x7, 0x40, 0x2, 
    0x2, 0x85, 0x86, 0x7, 0x9, 0x2, 0x2, 0x86, 0x88, 0x7, 0x40, 0x2, 0x2, 
    0x87, 0x85, 0x3, 0x2, 0x2, 0x2, 0x88, 0x8b, 0x3, 0x2, 0x2, 0x2, 0x89, 
    0x87, 0x3, 0x2, 0x2, 0x2, 0x89, 0x8a, 0x3, 0x2, 0x2, 0x2, 0x8a, 0x8c, 
    0x3, 0x2, 0x2, 0x2, 0x8b, 0x89, 0x3, 0x2, 0x2, 0x2, 0x8c, 0x119, 0x7, 
    0x4, 0x2, 0x2, 0x8d, 0x8e, 0x7, 0x11, 0x2, 0x2, 0x8e, 0x8f, 0x7, 0x12, 
    0x2, 0x2, 0x8f, 0x90, 0x7, 0x13, 0x2, 0x2, 0x90, 0x95, 0x5, 0x1e, 0x10, 
    0x2, 0x91, 0x92, 0x7, 0x9, 0x2, 0x2, 0x92, 0x94, 0x5, 0x1e, 0x10, 0x2, 
    0x93, 0x91, 0x3, 0x2, 0x2, 0x2, 0x94, 0x97, 0x3, 0x2, 0x2, 0x2, 0x95, 
    0x93, 0x3, 0x2, 0x2, 0x2, 0x95, 0x96, 0x3, 0x2, 0x2, 0x2, 0x96, 0x98, 
    0x3, 0x2, 0x2, 0x2, 0x97, 0x95, 0x3, 0x2, 0x2, 0x2, 0x98, 0x99, 0x7, 
    0x14, 0x2, 0x2, 0x99, 0x9a, 0x7, 0x4, 0x2, 0x2, 0x9a, 0x119, 0x3, 0x2, 
    0x2, 0x2, 0x9b, 0x9c, 0x7, 0x11, 0x2, 0x2, 0x9c, 0x9d, 0x5, 0x6, 0x4, 
    0x2, 0x9d, 0xaa, 0x5, 0xe, 0x8, 0x2, 0x9e, 0xa7, 0x7, 0x13, 0x2, 0x2, 
    0x9f, 0xa4, 0x5, 0x10, 0x9, 0x2, 0xa0, 0xa1, 0x7, 0x9, 0x2, 0x2, 0xa1, 
    0xa3, 0x5, 0x10, 0x9, 0x2, 0xa2, 0xa0, 0x3, 0x2, 0x2, 0x2, 0xa3, 0xa6, 
    0x3, 0x2, 0x2, 0x2, 0xa4, 0xa2, 0x3, 0x2, 0x2, 0x2, 0xa4, 0xa5, 0x3, 
    0x2, 0x2, 0x2, 0xa5, 0xa8, 0x3, 0x2, 0x2, 0x2, 0xa6, 0xa4, 0x3, 0x2, 
    0x2, 0x2, 0xa7, 0x9f, 0x3, 0x2, 0x2, 0x2, 0xa7, 0xa8, 0x3, 0x2, 0x2, 
    0x2, 0xa8, 0xa9, 0x3, 0x2, 0x2, 0x2, 0xa9, 0xab, 0x7, 0x14, 0x2, 0x2, 
    0xaa, 0x9e, 0x3, 0x2, 0x2, 0x2, 0xaa, 0xab, 0x3, 0x2, 0x2, 0x2, 0xab, 
    0xae, 0x3, 0x2, 0x2, 0x2, 0xac, 0xad, 0x7, 0x15, 0x2, 0x2, 0xad, 0xaf, 
    0x5, 0x12, 0xa, 0x2, 0xae, 0xac, 0x3, 0x2, 0x2, 0x2, 0xae, 0xaf, 0x3, 
    0x2, 0x2, 0x2, 0xaf, 0xb2, 0x3, 0x2, 0x2, 0x2, 0xb0, 0xb1, 0x7, 0x16, 
    0x2, 0x2, 0xb1, 0xb3, 0x5, 0x12, 0xa, 0x2, 0xb2, 0xb0, 0x3, 0x2, 0x2, 
    0x2, 0xb2, 0xb3, 0x3, 0x2, 0x2, 0x2, 0xb3, 0xb5, 0x3, 0x2, 0x2, 0x2, 
    0xb4, 0xb6, 0x5, 0x1c, 0xf, 0x2, 0xb5, 0xb4, 0x3, 0x2, 0x2, 0x2, 0xb5, 
    0xb6, 0x3, 0x2, 0x2, 0x2, 0xb6, 0xb7, 0x3, 0x2, 0x2, 0x2, 0xb7, 0xb8, 
    0x7, 0x4, 0x2, 0x2, 0xb8, 0x119, 0x3, 0x2, 0x2, 0x2, 0xb9, 0xbb, 0x5, 
    0x20, 0x11, 0x2, 0xba, 0xb9, 0x3, 0x2, 0x2, 0x2, 0xba, 0xbb, 0x3, 0x2, 
    0x2, 0x2, 0xbb, 0xbc, 0x3, 0x2, 0x2, 0x2, 0xbc, 0xbd, 0x5, 0x22, 0x12, 
    0x2, 0xbd, 0xbe, 0x5, 0x24, 0x13, 0x2, 0xbe, 0xbf, 0x7, 0x17, 0x2, 0x2, 
    0xbf, 0x119, 0x3, 0x2, 0x2, 0x2, 0xc0, 0xc1, 0x7, 0x12, 0x2, 0x2, 0xc1, 
    0xc2, 0x7, 0x40, 0x2, 0x2, 0xc2, 0xc6, 0x7, 0x8, 0x2, 0x2, 0xc3, 0xc5, 
    0x5, 0x32, 0x1a, 0x2, 0xc4, 0xc3, 0x3, 0x2, 0x2, 0x2, 0xc5, 0xc8, 0x3, 
    0x2, 0x2, 0x2, 0xc6, 0xc4, 0x3, 0x2, 0x2, 0x2, 0xc6, 0xc7, 0x3, 0x2, 
    0x2, 0x2, 0xc7, 0xc9, 0x3, 0x2, 0x2, 0x2, 0xc8, 0xc6, 0x3, 0x2, 0x2, 
    0x2, 0xc9, 0x119, 0x7, 0xa, 0x2, 0x2, 0xca, 0xcb, 0x7, 0x18, 0x2, 0x2, 
    0xcb, 0xcc, 0x5, 0x30, 0x19, 0x2, 0xcc, 0xcd, 0x7, 0x7, 0x2, 0x2, 0xcd, 
    0xce, 0x5, 0x42, 0x22, 0x2, 0xce, 0xcf, 0x7, 0x4, 0x2, 0x2, 0xcf, 0x119, 
    0x3, 0x2, 0x2, 0x2, 0xd0, 0xd1, 0x7, 0x19, 0x2, 0x2, 0xd1, 0xd2, 0x5, 
    0x34, 0x1b, 0x2, 0xd2, 0xd3, 0x7, 0x4, 0x2, 0x2, 0xd3, 0x119, 0x3, 0x2, 
    0x2, 0x2, 0xd4, 0xd5, 0x7, 0x1a, 0x2, 0x2, 0xd5, 0xd6, 0x5, 0x42, 0x22, 
    0x2, 0xd6, 0xd7, 0x7, 0x4, 0x2, 0x2, 0xd7, 0x119, 0x3, 0x2, 0x2, 0x2, 
    0xd8, 0xd9, 0x7, 0x1b, 0x2, 0x2, 0xd9, 0xda, 0x5, 0x42, 0x22, 0x2, 0xda, 
    0xdb, 0x7, 0x4, 0x2, 0x2, 0xdb, 0x119, 0x3, 0x2, 0x2, 0x2, 0xdc, 0xdd, 
    0x7, 0x1c, 0x2, 0x2, 0xdd, 0xde, 0x7, 0x1d, 0x2, 0x2, 0xde, 0xdf, 0x7, 
    0x40, 0x2, 0x2, 0xdf, 0xe0, 0x7, 0x1e, 0x2, 0x2, 0xe0, 0xe2, 0x7, 0x40, 
    0x2, 0x2, 0xe1, 0xe3, 0x5, 0x38, 0x1d, 0x2, 0xe2, 0xe1, 0x3, 0x2, 0x2, 
    0x2, 0xe2, 0xe3, 0x3, 0x2, 0x2, 0x2, 0xe3, 0xed, 0x3, 0x2, 0x2, 0x2, 
    0xe4, 0xe5, 0x7, 0x7, 0x2, 0x2, 0xe5, 0xea, 0x5, 0x42, 0x22, 0x2, 0xe6, 
    0xe7, 0x7, 0x9, 0x2, 0x2, 0xe7, 0xe9, 0x5, 0x42, 0x22, 0x2, 0xe8, 0xe6, 
    0x3, 0x2, 0x2, 0x2, 0xe9, 0xec, 0x3, 0x2, 0x2, 0x2, 0xea, 0xe8, 0x3, 
    0x2, 0x2, 0x2, 0xea, 0xeb, 0x3, 0x2, 0x2, 0x2, 0xeb, 0xee, 0x3, 0x2, 
    0x2, 0x2, 0xec, 0xea, 0x3, 0x2, 0x2, 0x2, 0xed, 0xe4, 0x3, 0x2, 0x2, 
    0x2, 0xed, 0xee, 0x3, 0x2, 0x2, 0x2, 0xee, 0xef, 0x3, 0x2, 0x2, 0x2, 
    0xef, 0x119, 0x7, 0x4, 0x2, 0x2, 0xf0, 0xf1, 0x7, 0x1c, 0x2, 0x2, 0xf1, 
    0xf3, 0x7, 0x40, 0x2, 0x2, 0xf2, 0xf4, 0x5, 0x38, 0x1d, 0x2, 0xf3, 0xf2, 
    0x3, 0x2, 0x2, 0x2, 0xf3, 0xf4, 0x3, 0x2, 0x2, 0x2, 0xf4, 0xf7, 0x3, 
    0x2, 0x2, 0x2, 0xf5, 0xf6, 0x7, 0x1f, 0x2, 0x2, 0xf6, 0xf8, 0x7, 0x40, 
    0x2, 0x2, 0xf7, 0xf5, 0x3, 0x2, 0x2, 0x2, 0xf7, 0xf8, 0x3, 0x2, 0x2, 
    0x2, 0xf8, 0x102, 0x3, 0x2, 0x2, 0x2, 0xf9, 0xfa, 0x7, 0x7, 0x2, 0x2, 
    0xfa, 0xff, 0x5, 0x42, 0x22, 0x2, 0xfb, 0xfc, 0x7, 0x9, 0x2, 0x2, 0xfc, 
    0xfe, 0x5, 0x42, 0x22, 0x2, 0xfd, 0xfb, 0x3, 0x2, 0x2, 0x2, 0xfe, 0x101, 
    0x3, 0x2, 0x2, 0x2, 0xff, 0xfd, 0x3, 0x2, 0x2, 0x2, 0xff, 0x100, 0x3, 
    0x2, 0x2, 0x2, 0x100, 0x103, 0x3, 0x2, 0x2, 0x2, 0x101, 0xff, 0x3, 0x2, 
    0x2, 0x2, 0x102, 0xf9, 0x3, 0x2, 0x2, 0x2, 0x102, 0x103, 0x3, 0x2, 0x2, 
    0x2, 0x103, 0x104, 0x3, 0x2, 0x2, 0x2, 0x104, 0x119, 0x7, 0x4, 0x2, 
    0x2, 0x105, 0x106, 0x7, 0x20, 0x2, 0x2, 0x106, 0x115, 0x7, 0x8, 0x2, 
    0x2, 0x107, 0x109, 0x5, 0x3c, 0x1f, 0x2, 0x108, 0x107, 0x3, 0x2, 0x2, 
    0x2, 0x109, 0x10c, 0x3, 0x2, 0x2, 0x2, 0x10a, 0x108, 0x3, 0x2, 0x2, 
    0x2, 0x10a, 0x10b, 0x3, 0x2, 0x2, 0x2, 0x10b, 0x116, 0x3, 0x2, 0x2, 
    0x2, 0x10c, 0x10a, 0x3, 0x2, 0x2, 0x2, 0x10d, 0x112, 0x5, 0x40, 0x21, 
    0x2, 0x10e, 0x10f, 0x7, 0x9, 0x2, 0x2, 0x10f, 0x111, 0x5, 0x40, 0x21, 
    0x2, 0x110, 0x10e, 0x3, 0x2, 0x2, 0x2, 0x111, 0x114, 0x3, 0x2, 0x2, 
    0x2, 0x112, 0x110, 0x3, 0x2, 0x2, 0x2, 0x112, 0x113, 0x3, 0x2, 0x2, 
    0x2, 0x113, 0x116, 0x3, 0x2, 0x2, 0x2, 0x114, 0x112, 0x3, 0x2, 0x2, 
    0x2, 0x115, 0x10a, 0x3, 0x2, 0x2, 0x2, 0x115, 0x10d, 0x3, 0x2, 0x2, 
    0x2, 0x116, 0x117, 0x3, 0x2, 0x2, 0x2, 0x117, 0x119, 0x7, 0xa, 0x2, 
    0x2, 0x118, 0x52, 0x3, 0x2, 0x2, 0x2, 0x118, 0x55, 0x3, 0x2, 0x2, 0x2, 
    0x118, 0x58, 0x3, 0x2, 0x2, 0x2, 0x118, 0x68, 0x3, 0x2, 0x2, 0x2, 0x118, 
    0x73, 0x3, 0x2, 0x2, 0x2, 0x118, 0x83, 0x3, 0x2, 0x2, 0x2, 0x118, 0x8d, 
    0x3, 0x2, 0x2, 0x2, 0x118, 0x9b, 0x3, 0x2, 0x2, 0x2, 0x118, 0xba, 0x3, 
    0x2, 0x2, 0x2, 0x118, 0xc0, 0x3, 0x2, 0x2, 0x2, 0x118, 0xca, 0x3, 0x2, 
    0x2, 0x2, 0x118, 0xd0, 0x3, 0x2, 0x2, 0x2, 0x118, 0xd4, 0x3, 0x2, 0x2, 
    0x2, 0x118, 0xd8, 0x3, 0x2, 0x2, 0x2, 0x118, 0xdc, 0x3, 0x2, 0x2, 0x2, 
    0x118, 0xf0, 0x3, 0x2, 0x2, 0x2, 0x118, 0x105, 0x3, 0x2, 0x2, 0x2, 0x119, 
    0x5, 0x3, 0x2, 0x2, 0x2, 0x11a, 0x11b, 0x9, 0x3, 0x2, 0x2, 0x11b, 0x7, 
    0x3, 0x2, 0x2, 0x2, 0x11c, 0x11d, 0x7, 0x40, 0x2, 0x2, 0x11d, 0x11e, 
    0x7, 0x13, 0x2, 0x2, 0x11e, 0x123, 0x5, 0xa, 0x6, 0x2, 0x11f, 0x120, 
    0x7, 0x9, 0x2, 0x2, 0x120, 0x122, 0x5, 0xa, 0x6, 0x2, 0x121, 0x11f, 
    0x3, 0x2, 0x2, 0x2, 0x122, 0x125, 0x3, 0x2, 0x2, 0x2, 0x123, 0x121, 
    0x3, 0x2, 0x2, 0x2, 0x123, 0x124, 0x3, 0x2, 0x2, 0x2, 0x124, 0x126, 
    0x3, 0x2, 0x2, 0x2, 0x125, 0x123, 0x3, 0x2, 0x2, 0x2, 0x126, 0x127, 
    0x7, 0x14, 0x2, 0x2, 0x127, 0x9, 0x3, 0x2, 0x2, 0x2, 0x128, 0x12a, 0x7, 
    0x40, 0x2, 0x2, 0x129, 0x12b, 0x7, 0x21, 0x2, 0x2, 0x12a, 0x129, 0x3, 
    0x2, 0x2, 0x2, 0x12a, 0x12b, 0x3, 0x2, 0x2, 0x2, 0x12b, 0xb, 0x3, 0x2, 
    0x2, 0x2, 0x12c, 0x12d, 0x7, 0x40, 0x2, 0x2, 0x12d, 0x12e, 0x7, 0x7, 
    0x2, 0x2, 0x12e, 0x12f, 0x5, 0x48, 0x25, 0x2, 0x12f, 0xd, 0x3, 0x2, 
    0x2, 0x2, 0x130, 0x135, 0x7, 0x40, 0x2, 0x2, 0x131, 0x132, 0x7, 0x17, 
    0x2, 0x2, 0x132, 0x134, 0x7, 0x40, 0x2, 0x2, 0x133, 0x131, 0x3, 0x2, 
    0x2, 0x2, 0x134, 0x137, 0x3, 0x2, 0x2, 0x2, 0x135, 0x133, 0x3, 0x2, 
    0x2, 0x2, 0x135, 0x136, 0x3, 0x2, 0x2, 0x2, 0x136, 0xf, 0x3, 0x2, 0x2, 
    0x2, 0x137, 0x135, 0x3, 0x2, 0x2, 0x2, 0x138, 0x139, 0x7, 0x40, 0x2, 
    0x2, 0x139, 0x13a, 0x7, 0x22, 0x2, 0x2, 0x13a, 0x13c, 0x5, 0x12, 0xa, 
    0x2, 0x13b, 0x13d, 0x5, 0x16, 0xc, 0x2, 0x13c, 0x13b, 0x3, 0x2, 0x2, 
    0x2, 0x13c, 0x13d, 0x3, 0x2, 0x2, 0x2, 0x13d, 0x13f, 0x3, 0x2, 0x2, 
    0x2, 0x13e, 0x140, 0x5, 0x1a, 0xe, 0x2, 0x13f, 0x13e, 0x3, 0x2, 0x2, 
    0x2, 0x13f, 0x140, 0x3, 0x2, 0x2, 0x2, 0x140, 0x143, 0x3, 0x2, 0x2, 
    0x2, 0x141, 0x142, 0x7, 0x7, 0x2, 0x2, 0x142, 0x144, 0x5, 0x46, 0x24, 
    0x2, 0x143, 0x141, 0x3, 0x2, 0x2, 0x2, 0x143, 0x144, 0x3, 0x2, 0x2, 
    0x2, 0x144, 0x11, 0x3, 0x2, 0x2, 0x2, 0x145, 0x149, 0x9, 0x4, 0x2, 0x2, 
    0x146, 0x148, 0x5, 0x14, 0xb, 0x2, 0x147, 0x146, 0x3, 0x2, 0x2, 0x2, 
    0x148, 0x14b, 0x3, 0x2, 0x2, 0x2, 0x149, 0x147, 0x3, 0x2, 0x2, 0x2, 
    0x149, 0x14a, 0x3, 0x2, 0x2, 0x2, 0x14a, 0x151, 0x3, 0x2, 0x2, 0x2, 
    0x14b, 0x149, 0x3, 0x2, 0x2, 0x2, 0x14c, 0x14d, 0x7, 0x23, 0x2, 0x2, 
    0x14d, 0x14e, 0x7, 0x24, 0x2, 0x2, 0x14e, 0x14f, 0x9, 0x4, 0x2, 0x2, 
    0x14f, 0x151, 0x7, 0x25, 0x2, 0x2, 0x150, 0x145, 0x3, 0x2, 0x2, 0x2, 
    0x150, 0x14c, 0x3, 0x2, 0x2, 0x2, 0x151, 0x13, 0x3, 0x2, 0x2, 0x2, 0x152, 
    0x154, 0x7, 0xe, 0x2, 0x2, 0x153, 0x155, 0x7, 0x3f, 0x2, 0x2, 0x154, 
    0x153, 0x3, 0x2, 0x2, 0x2, 0x154, 0x155, 0x3, 0x2, 0x2, 0x2, 0x155, 
    0x156, 0x3, 0x2, 0x2, 0x2, 0x156, 0x157, 0x7, 0xf, 0x2, 0x2, 0x157, 
    0x15, 0x3, 0x2, 0x2, 0x2, 0x158, 0x159, 0x7, 0x26, 0x2, 0x2, 0x159, 
    0x15a, 0x9, 0x5, 0x2, 0x2, 0x15a, 0x15b, 0x5, 0x18, 0xd, 0x2, 0x15b, 
    0x15c, 0x7, 0x9, 0x2, 0x2, 0x15c, 0x15d, 0x5, 0x18, 0xd, 0x2, 0x15d, 
    0x15e, 0x9, 0x6, 0x2, 0x2, 0x15e, 0x17, 0x3, 0x2, 0x2, 0x2, 0x15f, 0x165, 
    0x5, 0x48, 0x25, 0x2, 0x160, 0x162, 0x7, 0x27, 0x2, 0x2, 0x161, 0x160, 
    0x3, 0x2, 0x2, 0x2, 0x161, 0x162, 0x3, 0x2, 0x2, 0x2, 0x162, 0x163, 
    0x3, 0x2, 0x2, 0x2, 0x163, 0x165, 0x7, 0x28, 0x2, 0x2, 0x164, 0x15f, 
    0x3, 0x2, 0x2, 0x2, 0x164, 0x161, 0x3, 0x2, 0x2, 0x2, 0x165, 0x19, 0x3, 
    0x2, 0x2, 0x2, 0x166, 0x167, 0x7, 0x40, 0x2, 0x2, 0x167, 0x168, 0x5, 
    0x48, 0x25, 0x2, 0x168, 0x1b, 0x3, 0x2, 0x2, 0x2, 0x169, 0x16a, 0x7, 
    0x29, 0x2, 0x2, 0x16a, 0x16d, 0x7, 0x40, 0x2, 0x2, 0x16b, 0x16c, 0x7, 
    0x1e, 0x2, 0x2, 0x16c, 0x16e, 0x7, 0x40, 0x2, 0x2, 0x16d, 0x16b, 0x3, 
    0x2, 0x2, 0x2, 0x16d, 0x16e, 0x3, 0x2, 0x2, 0x2, 0x16e, 0x179, 0x3, 
    0x2, 0x2, 0x2, 0x16f, 0x170, 0x7, 0x2a, 0x2, 0x2, 0x170, 0x175, 0x7, 
    0x40, 0x2, 0x2, 0x171, 0x172, 0x7, 0x9, 0x2, 0x2, 0x172, 0x174, 0x7, 
    0x40, 0x2, 0x2, 0x173, 0x171, 0x3, 0x2, 0x2, 0x2, 0x174, 0x177, 0x3, 
    0x2, 0x2, 0x2, 0x175, 0x173, 0x3, 0x2, 0x2, 0x2, 0x175, 0x176, 0x3, 
    0x2, 0x2, 0x2, 0x176, 0x179, 0x3, 0x2, 0x2, 0x2, 0x177, 0x175, 0x3, 
    0x2, 0x2, 0x2, 0x178, 0x169, 0x3, 0x2, 0x2, 0x2, 0x178, 0x16f, 0x3, 
    0x2, 0x2, 0x2, 0x179, 0x1d, 0x3, 0x2, 0x2, 0x2, 0x17a, 0x180, 0x7, 0x40, 
    0x2, 0x2, 0x17b, 0x17d, 0x7, 0xe, 0x2, 0x2, 0x17c, 0x17e, 0x7, 0x40, 
    0x2, 0x2, 0x17d, 0x17c, 0x3, 0x2, 0x2, 0x2, 0x17d, 0x17e, 0x3, 0x2, 
    0x2, 0x2, 0x17e, 0x17f, 0x3, 0x2, 0x2, 0x2, 0x17f, 0x181, 0x7, 0xf, 
    0x2, 0x2, 0x180, 0x17b, 0x3, 0x2, 0x2, 0x2, 0x180, 0x181, 0x3, 0x2, 
    0x2, 0x2, 0x181, 0x182, 0x3, 0x2, 0x2, 0x2, 0x182, 0x183, 0x9, 0x7, 
    0x2, 0x2, 0x183, 0x1f, 0x3, 0x2, 0x2, 0x2, 0x184, 0x185, 0x7, 0x2d, 
    0x2, 0x2, 0x185, 0x186, 0x7, 0x40, 0x2, 0x2, 0x186, 0x21, 0x3, 0x2, 
    0x2, 0x2, 0x187, 0x189, 0x7, 0x2e, 0x2, 0x2, 0x188, 0x187, 0x3, 0x2, 
    0x2, 0x2, 0x188, 0x189, 0x3, 0x2, 0x2, 0x2, 0x189, 0x192, 0x3, 0x2, 
    0x2, 0x2, 0x18a, 0x18b, 0x7, 0x2f, 0x2, 0x2, 0x18b, 0x18c, 0x5, 0x48, 
    0x25, 0x2, 0x18c, 0x18d, 0x7, 0x22, 0x2, 0x2, 0x18d, 0x193, 0x3, 0x2, 
    0x2, 0x2, 0x18e, 0x18f, 0x7, 0x40, 0x2, 0x2, 0x18f, 0x190, 0x5, 0x48, 
    0x25, 0x2, 0x190, 0x191, 0x7, 0x22, 0x2, 0x2, 0x191, 0x193, 0x3, 0x2, 
    0x2, 0x2, 0x192, 0x18a, 0x3, 0x2, 0x2, 0x2, 0x192, 0x18e, 0x3, 0x2, 
    0x2, 0x2, 0x192, 0x193, 0x3, 0x2, 0x2, 0x2, 0x193, 0x23, 0x3, 0x2, 0x2, 
    0x2, 0x194, 0x195, 0x7, 0x30, 0x2, 0x2, 0x195, 0x196, 0x7, 0x31, 0x2, 
    0x2, 0x196, 0x197, 0x7, 0x32, 0x2, 0x2, 0x197, 0x19a, 0x5, 0x30, 0x19, 
    0x2, 0x198, 0x199, 0x7, 0x9, 0x2, 0x2, 0x199, 0x19b, 0x5, 0x30, 0x19, 
    0x2, 0x19a, 0x198, 0x3, 0x2, 0x2, 0x2, 0x19b, 0x19c, 0x3, 0x2, 0x2, 
    0x2, 0x19c, 0x19a, 0x3, 0x2, 0x2, 0x2, 0x19c, 0x19d, 0x3, 0x2, 0x2, 
    0x2, 0x19d, 0x1a0, 0x3, 0x2, 0x2, 0x2, 0x19e, 0x1a0, 0x5, 0x26, 0x14, 
    0x2, 0x19f, 0x194, 0x3, 0x2, 0x2, 0x2, 0x19f, 0x19e, 0x3, 0x2, 0x2, 
    0x2, 0x1a0, 0x25, 0x3, 0x2, 0x2, 0x2, 0x1a1, 0x1a6, 0x5, 0x28, 0x15, 
    0x2, 0x1a2, 0x1a3, 0x7, 0x33, 0x2, 0x2, 0x1a3, 0x1a5, 0x5, 0x28, 0x15, 
    0x2, 0x1a4, 0x1a2, 0x3, 0x2, 0x2, 0x2, 0x1a5, 0x1a8, 0x3, 0x2, 0x2, 
    0x2, 0x1a6, 0x1a4, 0x3, 0x2, 0x2, 0x2, 0x1a6, 0x1a7, 0x3, 0x2, 0x2, 
    0x2, 0x1a7, 0x27, 0x3, 0x2, 0x2, 0x2, 0x1a8, 0x1a6, 0x3, 0x2, 0x2, 0x2, 
    0x1a9, 0x1ae, 0x5, 0x2a, 0x16, 0x2, 0x1aa, 0x1ab, 0x7, 0x34, 0x2, 0x2, 
    0x1ab, 0x1ad, 0x5, 0x2a, 0x16, 0x2, 0x1ac, 0x1aa, 0x3, 0x2, 0x2, 0x2, 
    0x1ad, 0x1b0, 0x3, 0x2, 0x2, 0x2, 0x1ae, 0x1ac, 0x3, 0x2, 0x2, 0x2, 
    0x1ae, 0x1af, 0x3, 0x2, 0x2, 0x2, 0x1af, 0x29, 0x3, 0x2, 0x2, 0x2, 0x1b0, 
    0x1ae, 0x3, 0x2, 0x2, 0x2, 0x1b1, 0x1b6, 0x5, 0x2c, 0x17, 0x2, 0x1b2, 
    0x1b3, 0x7, 0x35, 0x2, 0x2, 0x1b3, 0x1b5, 0x5, 0x2c, 0x17, 0x2, 0x1b4, 
    0x1b2, 0x3, 0x2, 0x2, 0x2, 0x1b5, 0x1b8, 0x3, 0x2, 0x2, 0x2, 0x1b6, 
    0x1b4, 0x3, 0x2, 0x2, 0x2, 0x1b6, 0x1b7, 0x3, 0x2, 0x2, 0x2, 0x1b7, 
    0x2b, 0x3, 0x2, 0x2, 0x2, 0x1b8, 0x1b6, 0x3, 0x2, 0x2, 0x2, 0x1b9, 0x1be, 
    0x5, 0x2e, 0x18, 0x2, 0x1ba, 0x1bb, 0x7, 0x36, 0x2, 0x2, 0x1bb, 0x1bd, 
    0x5, 0x2e, 0x18, 0x2, 0x1bc, 0x1ba, 0x3, 0x2, 0x2, 0x2, 0x1bd, 0x1c0, 
    0x3, 0x2, 0x2, 0x2, 0x1be, 0x1bc, 0x3, 0x2, 0x2, 0x2, 0x1be, 0x1bf, 
    0x3, 0x2, 0x2, 0x2, 0x1bf, 0x2d, 0x3, 0x2, 0x2, 0x2, 0x1c0, 0x1be, 0x3, 
    0x2, 0x2, 0x2, 0x1c1, 0x1c2, 0x7, 0x21, 0x2, 0x2, 0x1c2, 0x1d4, 0x5, 
    0x2e, 0x18, 0x2, 0x1c3, 0x1c4, 0x7, 0x37, 0x2, 0x2, 0x1c4, 0x1c9, 0x7, 
    0x40, 0x2, 0x2, 0x1c5, 0x1c6, 0x7, 0x9, 0x2, 0x2, 0x1c6, 0x1c8, 0x7, 
    0x40, 0x2, 0x2, 0x1c7, 0x1c5, 0x3, 0x2, 0x2, 0x2, 0x1c8, 0x1cb, 0x3, 
    0x2, 0x2, 0x2, 0x1c9, 0x1c7, 0x3, 0x2, 0x2, 0x2, 0x1c9, 0x1ca, 0x3, 
    0x2, 0x2, 0x2, 0x1ca, 0x1cc, 0x3, 0x2, 0x2, 0x2, 0x1cb, 0x1c9, 0x3, 
    0x2, 0x2, 0x2, 0x1cc, 0x1cd, 0x7, 0x22, 0x2, 0x2, 0x1cd, 0x1d4, 0x5, 
    0x26, 0x14, 0x2, 0x1ce, 0x1d4, 0x5, 0x30, 0x19, 0x2, 0x1cf, 0x1d0, 0x7, 
    0x13, 0x2, 0x2, 0x1d0, 0x1d1, 0x5, 0x26, 0x14, 0x2, 0x1d1, 0x1d2, 0x7, 
    0x14, 0x2, 0x2, 0x1d2, 0x1d4, 0x3, 0x2, 0x2, 0x2, 0x1d3, 0x1c1, 0x3, 
    0x2, 0x2, 0x2, 0x1d3, 0x1c3, 0x3, 0x2, 0x2, 0x2, 0x1d3, 0x1ce, 0x3, 
    0x2, 0x2, 0x2, 0x1d3, 0x1cf, 0x3, 0x2, 0x2, 0x2, 0x1d4, 0x2f, 0x3, 0x2, 
    0x2, 0x2, 0x1d5, 0x1d6, 0x7, 0x40, 0x2, 0x2, 0x1d6, 0x1d7, 0x7, 0x13, 
    0x2, 0x2, 0x1d7, 0x1dc, 0x7, 0x40, 0x2, 0x2, 0x1d8, 0x1d9, 0x7, 0x9, 
    0x2, 0x2, 0x1d9, 0x1db, 0x7, 0x40, 0x2, 0x2, 0x1da, 0x1d8, 0x3, 0x2, 
    0x2, 0x2, 0x1db, 0x1de, 0x3, 0x2, 0x2, 0x2, 0x1dc, 0x1da, 0x3, 0x2, 
    0x2, 0x2, 0x1dc, 0x1dd, 0x3, 0x2, 0x2, 0x2, 0x1dd, 0x1df, 0x3, 0x2, 
    0x2, 0x2, 0x1de, 0x1dc, 0x3, 0x2, 0x2, 0x2, 0x1df, 0x1e0, 0x7, 0x14, 
    0x2, 0x2, 0x1e0, 0x31, 0x3, 0x2, 0x2, 0x2, 0x1e1, 0x1e2, 0x7, 0x40, 
    0x2, 0x2, 0x1e2, 0x1e4, 0x7, 0xe, 0x2, 0x2, 0x1e3, 0x1e5, 0x7, 0x40, 
    0x2, 0x2, 0x1e4, 0x1e3, 0x3, 0x2, 0x2, 0x2, 0x1e4, 0x1e5, 0x3, 0x2, 
    0x2, 0x2, 0x1e5, 0x1e6, 0x3, 0x2, 0x2, 0x2, 0x1e6, 0x1e7, 0x7, 0xf, 
    0x2, 0x2, 0x1e7, 0x1e8, 0x7, 0x22, 0x2, 0x2, 0x1e8, 0x1e9, 0x5, 0x12, 
    0xa, 0x2, 0x1e9, 0x1ea, 0x9, 0x7, 0x2, 0x2, 0x1ea, 0x1eb, 0x7, 0x4, 
    0x2, 0x2, 0x1eb, 0x1f3, 0x3, 0x2, 0x2, 0x2, 0x1ec, 0x1ed, 0x7, 0x40, 
    0x2, 0x2, 0x1ed, 0x1ee, 0x7, 0x22, 0x2, 0x2, 0x1ee, 0x1ef, 0x5, 0x12, 
    0xa, 0x2, 0x1ef, 0x1f0, 0x9, 0x7, 0x2, 0x2, 0x1f0, 0x1f1, 0x7, 0x4, 
    0x2, 0x2, 0x1f1, 0x1f3, 0x3, 0x2, 0x2, 0x2, 0x1f2, 0x1e1, 0x3, 0x2, 
    0x2, 0x2, 0x1f2, 0x1ec, 0x3, 0x2, 0x2, 0x2, 0x1f3, 0x33, 0x3, 0x2, 0x2, 
    0x2, 0x1f4, 0x1f5, 0x7, 0x38, 0x2, 0x2, 0x1f5, 0x1fa, 0x7, 0x40, 0x2, 
    0x2, 0x1f6, 0x1f7, 0x7, 0x9, 0x2, 0x2, 0x1f7, 0x1f9, 0x7, 0x40, 0x2, 
    0x2, 0x1f8, 0x1f6, 0x3, 0x2, 0x2, 0x2, 0x1f9, 0x1fc, 0x3, 0x2, 0x2, 
    0x2, 0x1fa, 0x1f8, 0x3, 0x2, 0x2, 0x2, 0x1fa, 0x1fb, 0x3, 0x2, 0x2, 
    0x2, 0x1fb, 0x206, 0x3, 0x2, 0x2, 0x2, 0x1fc, 0x1fa, 0x3, 0x2, 0x2, 
    0x2, 0x1fd, 0x1fe, 0x7, 0x39, 0x2, 0x2, 0x1fe, 0x203, 0x5, 0x36, 0x1c, 
    0x2, 0x1ff, 0x200, 0x7, 0x3a, 0x2, 0x2, 0x200, 0x202, 0x5, 0x36, 0x1c, 
    0x2, 0x201, 0x1ff, 0x3, 0x2, 0x2, 0x2, 0x202, 0x205, 0x3, 0x2, 0x2, 
    0x2, 0x203, 0x201, 0x3, 0x2, 0x2, 0x2, 0x203, 0x204, 0x3, 0x2, 0x2, 
    0x2, 0x204, 0x207, 0x3, 0x2, 0x2, 0x2, 0x205, 0x203, 0x3, 0x2, 0x2, 
    0x2, 0x206, 0x1fd, 0x3, 0x2, 0x2, 0x2, 0x206, 0x207, 0x3, 0x2, 0x2, 
    0x2, 0x207, 0x208, 0x3, 0x2, 0x2, 0x2, 0x208, 0x209, 0x7, 0x22, 0x2, 
    0x2, 0x209, 0x20c, 0x5, 0x42, 0x22, 0x2, 0x20a, 0x20c, 0x5, 0x42, 0x22, 
    0x2, 0x20b, 0x1f4, 0x3, 0x2, 0x2, 0x2, 0x20b, 0x20a, 0x3, 0x2, 0x2, 
    0x2, 0x20c, 0x35, 0x3, 0x2, 0x2, 0x2, 0x20d, 0x20e, 0x7, 0x40, 0x2, 
    0x2, 0x20e, 0x20f, 0x7, 0x13, 0x2, 0x2, 0x20f, 0x210, 0x5, 0x30, 0x19, 
    0x2, 0x210, 0x211, 0x7, 0x14, 0x2, 0x2, 0x211, 0x212, 0x9, 0x8, 0x2, 
    0x2, 0x212, 0x213, 0x5, 0x48, 0x25, 0x2, 0x213, 0x219, 0x3, 0x2, 0x2, 
    0x2, 0x214, 0x216, 0x7, 0x21, 0x2, 0x2, 0x215, 0x214, 0x3, 0x2, 0x2, 
    0x2, 0x215, 0x216, 0x3, 0x2, 0x2, 0x2, 0x216, 0x217, 0x3, 0x2, 0x2, 
    0x2, 0x217, 0x219, 0x5, 0x30, 0x19, 0x2, 0x218, 0x20d, 0x3, 0x2, 0x2, 
    0x2, 0x218, 0x215, 0x3, 0x2, 0x2, 0x2, 0x219, 0x37, 0x3, 0x2, 0x2, 0x2, 
    0x21a, 0x21b, 0x7, 0x13, 0x2, 0x2, 0x21b, 0x220, 0x5, 0x3a, 0x1e, 0x2, 
    0x21c, 0x21d, 0x7, 0x9, 0x2, 0x2, 0x21d, 0x21f, 0x5, 0x3a, 0x1e, 0x2, 
    0x21e, 0x21c, 0x3, 0x2, 0x2, 0x2, 0x21f, 0x222, 0x3, 0x2, 0x2, 0x2, 
    0x220, 0x21e, 0x3, 0x2, 0x2, 0x2, 0x220, 0x221, 0x3, 0x2, 0x2, 0x2, 
    0x221, 0x223, 0x3, 0x2, 0x2, 0x2, 0x222, 0x220, 0x3, 0x2, 0x2, 0x2, 
    0x223, 0x224, 0x7, 0x14, 0x2, 0x2, 0x224, 0x39, 0x3, 0x2, 0x2, 0x2, 
    0x225, 0x226, 0x7, 0x40, 0x2, 0x2, 0x226, 0x227, 0x7, 0x22, 0x2, 0x2, 
    0x227, 0x228, 0x7, 0x40, 0x2, 0x2, 0x228, 0x3b, 0x3, 0x2, 0x2, 0x2, 
    0x229, 0x22a, 0x7, 0xe, 0x2, 0x2, 0x22a, 0x22b, 0x5, 0x48, 0x25, 0x2, 
    0x22b, 0x22c, 0x7, 0x9, 0x2, 0x2, 0x22c, 0x22d, 0x5, 0x3e, 0x20, 0x2, 
    0x22d, 0x22e, 0x7, 0x14, 0x2, 0x2, 0x22e, 0x22f, 0x7, 0x22, 0x2, 0x2, 
    0x22f, 0x231, 0x3, 0x2, 0x2, 0x2, 0x230, 0x229, 0x3, 0x2, 0x2, 0x2, 
    0x230, 0x231, 0x3, 0x2, 0x2, 0x2, 0x231, 0x232, 0x3, 0x2, 0x2, 0x2, 
    0x232, 0x23b, 0x7, 0x8, 0x2, 0x2, 0x233, 0x238, 0x5, 0x40, 0x21, 0x2, 
    0x234, 0x235, 0x7, 0x9, 0x2, 0x2, 0x235, 0x237, 0x5, 0x40, 0x21, 0x2, 
    0x236, 0x234, 0x3, 0x2, 0x2, 0x2, 0x237, 0x23a, 0x3, 0x2, 0x2, 0x2, 
    0x238, 0x236, 0x3, 0x2, 0x2, 0x2, 0x238, 0x239, 0x3, 0x2, 0x2, 0x2, 
    0x239, 0x23c, 0x3, 0x2, 0x2, 0x2, 0x23a, 0x238, 0x3, 0x2, 0x2, 0x2, 
    0x23b, 0x233, 0x3, 0x2, 0x2, 0x2, 0x23b, 0x23c, 0x3, 0x2, 0x2, 0x2, 
    0x23c, 0x23d, 0x3, 0x2, 0x2, 0x2, 0x23d, 0x23f, 0x7, 0xa, 0x2, 0x2, 
    0x23e, 0x240, 0x7, 0x4, 0x2, 0x2, 0x23f, 0x23e, 0x3, 0x2, 0x2, 0x2, 
    0x23f, 0x240, 0x3, 0x2, 0x2, 0x2, 0x240, 0x3d, 0x3, 0x2, 0x2, 0x2, 0x241, 
    0x244, 0x5, 0x48, 0x25, 0x2, 0x242, 0x244, 0x7, 0x28, 0x2, 0x2, 0x243, 
    0x241, 0x3, 0x2, 0x2, 0x2, 0x243, 0x242, 0x3, 0x2, 0x2, 0x2, 0x244, 
    0x3f, 0x3, 0x2, 0x2, 0x2, 0x245, 0x246, 0x7, 0x40, 0x2, 0x2, 0x246, 
    0x247, 0x7, 0x22, 0x2, 0x2, 0x247, 0x248, 0x5, 0x48, 0x25, 0x2, 0x248, 
    0x41, 0x3, 0x2, 0x2, 0x2, 0x249, 0x256, 0x5, 0xe, 0x8, 0x2, 0x24a, 0x253, 
    0x7, 0x13, 0x2, 0x2, 0x24b, 0x250, 0x5, 0x44, 0x23, 0x2, 0x24c, 0x24d, 
    0x7, 0x9, 0x2, 0x2, 0x24d, 0x24f, 0x5, 0x44, 0x23, 0x2, 0x24e, 0x24c, 
    0x3, 0x2, 0x2, 0x2, 0x24f, 0x252, 0x3, 0x2, 0x2, 0x2, 0x250, 0x24e, 
    0x3, 0x2, 0x2, 0x2, 0x250, 0x251, 0x3, 0x2, 0x2, 0x2, 0x251, 0x254, 
    0x3, 0x2, 0x2, 0x2, 0x252, 0x250, 0x3, 0x2, 0x2, 0x2, 0x253, 0x24b, 
    0x3, 0x2, 0x2, 0x2, 0x253, 0x254, 0x3, 0x2, 0x2, 0x2, 0x254, 0x255, 
    0x3, 0x2, 0x2, 0x2, 0x255, 0x257, 0x7, 0x14, 0x2, 0x2, 0x256, 0x24a, 
    0x3, 0x2, 0x2, 0x2, 0x256, 0x257, 0x3, 0x2, 0x2, 0x2, 0x257, 0x43, 0x3, 
    0x2, 0x2, 0x2, 0x258, 0x259, 0x7, 0x40, 0x2, 0x2, 0x259, 0x25b, 0x7, 
    0x7, 0x2, 0x2, 0x25a, 0x258, 0x3, 0x2, 0x2, 0x2, 0x25a, 0x25b, 0x3, 
    0x2, 0x2, 0x2, 0x25b, 0x25c, 0x3, 0x2, 0x2, 0x2, 0x25c, 0x25d, 0x5, 
    0x46, 0x24, 0x2, 0x25d, 0x45, 0x3, 0x2, 0x2, 0x2, 0x25e, 0x28e, 0x5, 
    0x48, 0x25, 0x2, 0x25f, 0x28e, 0x7, 0x41, 0x2, 0x2, 0x260, 0x28e, 0x9, 
    0x9, 0x2, 0x2, 0x261, 0x28e, 0x7, 0x28, 0x2, 0x2, 0x262, 0x263, 0x7, 
    0x40, 0x2, 0x2, 0x263, 0x264, 0x7, 0xe, 0x2, 0x2, 0x264, 0x265, 0x7, 
    0x40, 0x2, 0x2, 0x265, 0x28e, 0x7, 0xf, 0x2, 0x2, 0x266, 0x267, 0x5, 
    0xe, 0x8, 0x2, 0x267, 0x270, 0x7, 0x13, 0x2, 0x2, 0x268, 0x26d, 0x5, 
    0x44, 0x23, 0x2, 0x269, 0x26a, 0x7, 0x9, 0x2, 0x2, 0x26a, 0x26c, 0x5, 
    0x44, 0x23, 0x2, 0x26b, 0x269, 0x3, 0x2, 0x2, 0x2, 0x26c, 0x26f, 0x3, 
    0x2, 0x2, 0x2, 0x26d, 0x26b, 0x3, 0x2, 0x2, 0x2, 0x26d, 0x26e, 0x3, 
    0x2, 0x2, 0x2, 0x26e, 0x271, 0x3, 0x2, 0x2, 0x2, 0x26f, 0x26d, 0x3, 
    0x2, 0x2, 0x2, 0x270, 0x268, 0x3, 0x2, 0x2, 0x2, 0x270, 0x271, 0x3, 
    0x2, 0x2, 0x2, 0x271, 0x272, 0x3, 0x2, 0x2, 0x2, 0x272, 0x273, 0x7, 
    0x14, 0x2, 0x2, 0x273, 0x28e, 0x3, 0x2, 0x2, 0x2, 0x274, 0x28e, 0x7, 
    0x40, 0x2, 0x2, 0x275, 0x27e, 0x7, 0xe, 0x2, 0x2, 0x276, 0x27b, 0x5, 
    0x46, 0x24, 0x2, 0x277, 0x278, 0x7, 0x9, 0x2, 0x2, 0x278, 0x27a, 0x5, 
    0x46, 0x24, 0x2, 0x279, 0x277, 0x3, 0x2, 0x2, 0x2, 0x27a, 0x27d, 0x3, 
    0x2, 0x2, 0x2, 0x27b, 0x279, 0x3, 0x2, 0x2, 0x2, 0x27b, 0x27c, 0x3, 
    0x2, 0x2, 0x2, 0x27c, 0x27f, 0x3, 0x2, 0x2, 0x2, 0x27d, 0x27b, 0x3, 
    0x2, 0x2, 0x2, 0x27e, 0x276, 0x3, 0x2, 0x2, 0x2, 0x27e, 0x27f, 0x3, 
    0x2, 0x2, 0x2, 0x27f, 0x280, 0x3, 0x2, 0x2, 0x2, 0x280, 0x28e, 0x7, 
    0xf, 0x2, 0x2, 0x281, 0x28a, 0x7, 0x8, 0x2, 0x2, 0x282, 0x287, 0x5, 
    0x46, 0x24, 0x2, 0x283, 0x284, 0x7, 0x9, 0x2, 0x2, 0x284, 0x286, 0x5, 
    0x46, 0x24, 0x2, 0x285, 0x283, 0x3, 0x2, 0x2, 0x2, 0x286, 0x289, 0x3, 
    0x2, 0x2, 0x2, 0x287, 0x285, 0x3, 0x2, 0x2, 0x2, 0x287, 0x288, 0x3, 
    0x2, 0x2, 0x2, 0x288, 0x28b, 0x3, 0x2, 0x2, 0x2, 0x289, 0x287, 0x3, 
    0x2, 0x2, 0x2, 0x28a, 0x282, 0x3, 0x2, 0x2, 0x2, 0x28a, 0x28b, 0x3, 
    0x2, 0x2, 0x2, 0x28b, 0x28c, 0x3, 0x2, 0x2, 0x2, 0x28c, 0x28e, 0x7, 
    0xa, 0x2, 0x2, 0x28d, 0x25e, 0x3, 0x2, 0x2, 0x2, 0x28d, 0x25f, 0x3, 
    0x2, 0x2, 0x2, 0x28d, 0x260, 0x3, 0x2, 0x2, 0x2, 0x28d, 0x261, 0x3, 
    0x2, 0x2, 0x2, 0x28d, 0x262, 0x3, 0x2, 0x2, 0x2, 0x28d, 0x266, 0x3, 
    0x2, 0x2, 0x2, 0x28d, 0x274, 0x3, 0x2, 0x2, 0x2, 0x28d, 0x275, 0x3, 
    0x2, 0x2, 0x2, 0x28d, 0x281, 0x3, 0x2, 0x2, 0x2, 0x28e, 0x47, 0x3, 0x2, 
    0x2, 0x2, 0x28f, 0x291, 0x7, 0x27, 0x2, 0x2, 0x290, 0x28f, 0x3, 0x2, 
    0x2, 0x2, 0x290, 0x291, 0x3, 0x2, 0x2, 0x2, 0x291, 0x292, 0x3, 0x2, 
    0x2, 0x2, 0x292, 0x294, 0x7, 0x3f, 0x2, 0x2, 0x293, 0x295, 0x7, 0x40, 
    0x2, 0x2, 0x294, 0x293, 0x3, 0x2, 0x2, 0x2, 0x294, 0x295, 0x3, 0x2, 
    0x2, 0x2, 0x295, 0x49, 0x3, 0x2, 0x2, 0x2, 0x53, 0x4d, 0x61, 0x65, 0x6e, 
    0x7b, 0x80, 0x89, 0x95, 0xa4, 0xa7, 0xaa, 0xae, 0xb2, 0xb5, 0xba, 0xc6, 
    0xe2, 0xea, 0xed, 0xf3, 0xf7, 0xff, 0x102, 0x10a, 0x112, 0x115, 0x118, 
    0x123, 0x12a, 0x135, 0x13c, 0x13f, 0x143, 0x149, 0x150, 0x154, 0x161, 
    0x164, 0x16d, 0x175, 0x178, 0x17d, 0x180, 0x188, 0x192, 0x19c, 0x19f, 
    0x1a6, 0x1ae, 0x1b6, 0x1be, 0x1c9, 0x1d3, 0x1dc, 0x1e4, 0x1f2, 0x1fa, 
    0x203, 0x206, 0x20b, 0x215, 0x218, 0x220, 0x230, 0x238, 0x23b, 0x23f, 
    0x243, 0x250, 0x253, 0x256, 0x25a, 0x26d, 0x270, 0x27b, 0x27e, 0x287, 
    0x28a, 0x28d, 0x290, 0x294, 
  };

  atn::ATNDeserializer deserializer;
  _atn = deserializer.deserialize(_serializedATN);

  size_t count = _atn.getNumberOfDecisions();
  _decisionToDFA.reserve(count);
  for (size_t i = 0; i < count; i++) { 
    _decisionToDFA.emplace_back(_atn.getDecisionState(i), i);
  }
}

KsmParser::Initializer KsmParser::_init;

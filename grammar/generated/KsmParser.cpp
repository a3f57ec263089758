
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
    setState(61);
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
      | (1ULL << KsmParser::T__19)
      | (1ULL << KsmParser::T__20)
      | (1ULL << KsmParser::T__21)
      | (1ULL << KsmParser::T__22)
      | (1ULL << KsmParser::T__23)
      | (1ULL << KsmParser::T__27)
      | (1ULL << KsmParser::T__28)
      | (1ULL << KsmParser::T__33)
      | (1ULL << KsmParser::T__34)
      | (1ULL << KsmParser::T__35)
      | (1ULL << KsmParser::T__42)
      | (1ULL << KsmParser::IDENT))) != 0)) {
      setState(58);
      item();
      setState(63);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(64);
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

KsmParser::TypeRefContext* KsmParser::ExternItemContext::typeRef() {
  return getRuleContext<KsmParser::TypeRefContext>(0);
}

std::vector<KsmParser::ParamContext *> KsmParser::ExternItemContext::param() {
  return getRuleContexts<KsmParser::ParamContext>();
}

KsmParser::ParamContext* KsmParser::ExternItemContext::param(size_t i) {
  return getRuleContext<KsmParser::ParamContext>(i);
}

KsmParser::ExternItemContext::ExternItemContext(ItemContext *ctx) { copyFrom(ctx); }


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
    setState(236);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 22, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::DomainItemContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(66);
      match(KsmParser::T__0);
      setState(67);
      match(KsmParser::IDENT);
      setState(68);
      match(KsmParser::T__1);
      break;
    }

    case 2: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::IncludeItemContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(69);
      match(KsmParser::T__2);
      setState(70);
      match(KsmParser::STRING);
      setState(71);
      match(KsmParser::T__1);
      break;
    }

    case 3: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::TypeItemContext>(_localctx));
      enterOuterAlt(_localctx, 3);
      setState(72);
      match(KsmParser::T__3);
      setState(73);
      match(KsmParser::IDENT);
      setState(85);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__4) {
        setState(74);
        match(KsmParser::T__4);
        setState(75);
        match(KsmParser::T__5);
        setState(76);
        match(KsmParser::IDENT);
        setState(81);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(77);
          match(KsmParser::T__6);
          setState(78);
          match(KsmParser::IDENT);
          setState(83);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(84);
        match(KsmParser::T__7);
      }
      setState(87);
      match(KsmParser::T__1);
      break;
    }

    case 4: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::PredItemContext>(_localctx));
      enterOuterAlt(_localctx, 4);
      setState(88);
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
      setState(89);
      predSig();
      setState(94);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::T__6) {
        setState(90);
        match(KsmParser::T__6);
        setState(91);
        predSig();
        setState(96);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(97);
      match(KsmParser::T__1);
      break;
    }

    case 5: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::QuantityItemContext>(_localctx));
      enterOuterAlt(_localctx, 5);
      setState(99);
      match(KsmParser::T__10);
      setState(100);
      match(KsmParser::IDENT);
      setState(112);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__11) {
        setState(101);
        match(KsmParser::T__11);
        setState(102);
        unitDef();
        setState(107);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(103);
          match(KsmParser::T__6);
          setState(104);
          unitDef();
          setState(109);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(110);
        match(KsmParser::T__12);
      }
      setState(114);
      match(KsmParser::T__1);
      break;
    }

    case 6: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ValueItemContext>(_localctx));
      enterOuterAlt(_localctx, 6);
      setState(115);
      match(KsmParser::T__13);
      setState(116);
      match(KsmParser::IDENT);
      setState(121);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::T__6) {
        setState(117);
        match(KsmParser::T__6);
        setState(118);
        match(KsmParser::IDENT);
        setState(123);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(124);
      match(KsmParser::T__1);
      break;
    }

    case 7: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ExternItemContext>(_localctx));
      enterOuterAlt(_localctx, 7);
      setState(125);
      match(KsmParser::T__14);
      setState(126);
      externKind();
      setState(127);
      qualName();
      setState(140);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__15) {
        setState(128);
        match(KsmParser::T__15);
        setState(137);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == KsmParser::IDENT) {
          setState(129);
          param();
          setState(134);
          _errHandler->sync(this);
          _la = _input->LA(1);
          while (_la == KsmParser::T__6) {
            setState(130);
            match(KsmParser::T__6);
            setState(131);
            param();
            setState(136);
            _errHandler->sync(this);
            _la = _input->LA(1);
          }
        }
        setState(139);
        match(KsmParser::T__16);
      }
      setState(144);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__17) {
        setState(142);
        match(KsmParser::T__17);
        setState(143);
        typeRef();
      }
      setState(146);
      match(KsmParser::T__1);
      break;
    }

    case 8: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::RuleItemContext>(_localctx));
      enterOuterAlt(_localctx, 8);
      setState(148);
      ruleHead();
      setState(149);
      ruleBody();
      setState(150);
      match(KsmParser::T__18);
      break;
    }

    case 9: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ModelItemContext>(_localctx));
      enterOuterAlt(_localctx, 9);
      setState(152);
      match(KsmParser::T__19);
      setState(153);
      match(KsmParser::IDENT);
      setState(154);
      match(KsmParser::T__5);
      setState(158);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::IDENT) {
        setState(155);
        modelVar();
        setState(160);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(161);
      match(KsmParser::T__7);
      break;
    }

    case 10: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ExtractItemContext>(_localctx));
      enterOuterAlt(_localctx, 10);
      setState(162);
      match(KsmParser::T__20);
      setState(163);
      atom();
      setState(164);
      match(KsmParser::T__4);
      setState(165);
      call();
      setState(166);
      match(KsmParser::T__1);
      break;
    }

    case 11: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::PriorItemContext>(_localctx));
      enterOuterAlt(_localctx, 11);
      setState(168);
      match(KsmParser::T__21);
      setState(169);
      priorForm();
      setState(170);
      match(KsmParser::T__1);
      break;
    }

    case 12: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::LikelihoodItemContext>(_localctx));
      enterOuterAlt(_localctx, 12);
      setState(172);
      match(KsmParser::T__22);
      setState(173);
      call();
      setState(174);
      match(KsmParser::T__1);
      break;
    }

    case 13: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::KernelPairItemContext>(_localctx));
      enterOuterAlt(_localctx, 13);
      setState(176);
      match(KsmParser::T__23);
      setState(177);
      match(KsmParser::T__24);
      setState(178);
      match(KsmParser::IDENT);
      setState(179);
      match(KsmParser::T__25);
      setState(180);
      match(KsmParser::IDENT);
      setState(182);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__15) {
        setState(181);
        kernelParams();
      }
      setState(193);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__4) {
        setState(184);
        match(KsmParser::T__4);
        setState(185);
        call();
        setState(190);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(186);
          match(KsmParser::T__6);
          setState(187);
          call();
          setState(192);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(195);
      match(KsmParser::T__1);
      break;
    }

    case 14: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::KernelItemContext>(_localctx));
      enterOuterAlt(_localctx, 14);
      setState(196);
      match(KsmParser::T__23);
      setState(197);
      match(KsmParser::IDENT);
      setState(199);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__15) {
        setState(198);
        kernelParams();
      }
      setState(203);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__26) {
        setState(201);
        match(KsmParser::T__26);
        setState(202);
        match(KsmParser::IDENT);
      }
      setState(214);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__4) {
        setState(205);
        match(KsmParser::T__4);
        setState(206);
        call();
        setState(211);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(207);
          match(KsmParser::T__6);
          setState(208);
          call();
          setState(213);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(216);
      match(KsmParser::T__1);
      break;
    }

    case 15: {
      _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<KsmParser::ScheduleItemContext>(_localctx));
      enterOuterAlt(_localctx, 15);
      setState(217);
      match(KsmParser::T__27);
      setState(218);
      match(KsmParser::T__5);
      setState(233);
      _errHandler->sync(this);
      switch (_input->LA(1)) {
        case KsmParser::T__5:
        case KsmParser::T__7:
        case KsmParser::T__11: {
          setState(222);
          _errHandler->sync(this);
          _la = _input->LA(1);
          while (_la == KsmParser::T__5

          || _la == KsmParser::T__11) {
            setState(219);
            scheduleRow();
            setState(224);
            _errHandler->sync(this);
            _la = _input->LA(1);
          }
          break;
        }

        case KsmParser::IDENT: {
          setState(225);
          scheduleEntry();
          setState(230);
          _errHandler->sync(this);
          _la = _input->LA(1);
          while (_la == KsmParser::T__6) {
            setState(226);
            match(KsmParser::T__6);
            setState(227);
            scheduleEntry();
            setState(232);
            _errHandler->sync(this);
            _la = _input->LA(1);
          }
          break;
        }

      default:
        throw NoViableAltException(this);
      }
      setState(235);
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
    setState(238);
    _la = _input->LA(1);
    if (!((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << KsmParser::T__21)
      | (1ULL << KsmParser::T__22)
      | (1ULL << KsmParser::T__23)
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
    setState(240);
    match(KsmParser::IDENT);
    setState(241);
    match(KsmParser::T__15);
    setState(242);
    predArg();
    setState(247);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == KsmParser::T__6) {
      setState(243);
      match(KsmParser::T__6);
      setState(244);
      predArg();
      setState(249);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(250);
    match(KsmParser::T__16);
   
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
    setState(252);
    match(KsmParser::IDENT);
    setState(254);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__28) {
      setState(253);
      dynamic_cast<PredArgContext *>(_localctx)->excl = match(KsmParser::T__28);
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
    setState(256);
    match(KsmParser::IDENT);
    setState(257);
    match(KsmParser::T__4);
    setState(258);
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
    setState(260);
    match(KsmParser::IDENT);
    setState(265);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == KsmParser::T__18) {
      setState(261);
      match(KsmParser::T__18);
      setState(262);
      match(KsmParser::IDENT);
      setState(267);
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
    setState(268);
    match(KsmParser::IDENT);
    setState(269);
    match(KsmParser::T__29);
    setState(270);
    typeRef();
    setState(273);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__4) {
      setState(271);
      match(KsmParser::T__4);
      setState(272);
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
    setState(287);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::IDENT: {
        _localctx = dynamic_cast<TypeRefContext *>(_tracker.createInstance<KsmParser::NamedTypeContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(275);
        match(KsmParser::IDENT);
        setState(280);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__11) {
          setState(276);
          match(KsmParser::T__11);
          setState(277);
          match(KsmParser::T__12);
          setState(282);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        break;
      }

      case KsmParser::T__30: {
        _localctx = dynamic_cast<TypeRefContext *>(_tracker.createInstance<KsmParser::SetTypeContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(283);
        match(KsmParser::T__30);
        setState(284);
        match(KsmParser::T__31);
        setState(285);
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
        setState(286);
        match(KsmParser::T__32);
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
  enterRule(_localctx, 18, KsmParser::RuleRuleHead);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(290);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__33) {
      setState(289);
      dynamic_cast<RuleHeadContext *>(_localctx)->hard = match(KsmParser::T__33);
    }
    setState(300);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 30, _ctx)) {
    case 1: {
      setState(292);
      dynamic_cast<RuleHeadContext *>(_localctx)->weightProb = match(KsmParser::T__34);
      setState(293);
      number();
      setState(294);
      match(KsmParser::T__29);
      break;
    }

    case 2: {
      setState(296);
      dynamic_cast<RuleHeadContext *>(_localctx)->weightRaw = match(KsmParser::IDENT);
      setState(297);
      number();
      setState(298);
      match(KsmParser::T__29);
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
  enterRule(_localctx, 20, KsmParser::RuleRuleBody);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(313);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__35: {
        _localctx = dynamic_cast<RuleBodyContext *>(_tracker.createInstance<KsmParser::ExactlyOneBodyContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(302);
        match(KsmParser::T__35);
        setState(303);
        match(KsmParser::T__36);
        setState(304);
        match(KsmParser::T__37);
        setState(305);
        atom();
        setState(308); 
        _errHandler->sync(this);
        _la = _input->LA(1);
        do {
          setState(306);
          match(KsmParser::T__6);
          setState(307);
          atom();
          setState(310); 
          _errHandler->sync(this);
          _la = _input->LA(1);
        } while (_la == KsmParser::T__6);
        break;
      }

      case KsmParser::T__15:
      case KsmParser::T__28:
      case KsmParser::T__42:
      case KsmParser::IDENT: {
        _localctx = dynamic_cast<RuleBodyContext *>(_tracker.createInstance<KsmParser::FormulaBodyContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(312);
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
  enterRule(_localctx, 22, KsmParser::RuleFormula);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(315);
    implication();
    setState(320);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 33, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        setState(316);
        match(KsmParser::T__38);
        setState(317);
        implication(); 
      }
      setState(322);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 33, _ctx);
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
  enterRule(_localctx, 24, KsmParser::RuleImplication);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(323);
    disjunction();
    setState(328);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 34, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        setState(324);
        match(KsmParser::T__39);
        setState(325);
        disjunction(); 
      }
      setState(330);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 34, _ctx);
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
  enterRule(_localctx, 26, KsmParser::RuleDisjunction);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(331);
    conjunction();
    setState(336);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 35, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        setState(332);
        match(KsmParser::T__40);
        setState(333);
        conjunction(); 
      }
      setState(338);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 35, _ctx);
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
  enterRule(_localctx, 28, KsmParser::RuleConjunction);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(339);
    unary();
    setState(344);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 36, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        setState(340);
        match(KsmParser::T__41);
        setState(341);
        unary(); 
      }
      setState(346);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 36, _ctx);
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
  enterRule(_localctx, 30, KsmParser::RuleUnary);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(365);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__28: {
        _localctx = dynamic_cast<UnaryContext *>(_tracker.createInstance<KsmParser::NotFormulaContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(347);
        match(KsmParser::T__28);
        setState(348);
        unary();
        break;
      }

      case KsmParser::T__42: {
        _localctx = dynamic_cast<UnaryContext *>(_tracker.createInstance<KsmParser::ExistsFormulaContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(349);
        match(KsmParser::T__42);
        setState(350);
        match(KsmParser::IDENT);
        setState(355);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(351);
          match(KsmParser::T__6);
          setState(352);
          match(KsmParser::IDENT);
          setState(357);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(358);
        match(KsmParser::T__29);
        setState(359);
        formula();
        break;
      }

      case KsmParser::IDENT: {
        _localctx = dynamic_cast<UnaryContext *>(_tracker.createInstance<KsmParser::AtomFormulaContext>(_localctx));
        enterOuterAlt(_localctx, 3);
        setState(360);
        atom();
        break;
      }

      case KsmParser::T__15: {
        _localctx = dynamic_cast<UnaryContext *>(_tracker.createInstance<KsmParser::ParenFormulaContext>(_localctx));
        enterOuterAlt(_localctx, 4);
        setState(361);
        match(KsmParser::T__15);
        setState(362);
        formula();
        setState(363);
        match(KsmParser::T__16);
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
  enterRule(_localctx, 32, KsmParser::RuleAtom);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(367);
    match(KsmParser::IDENT);
    setState(368);
    match(KsmParser::T__15);
    setState(369);
    match(KsmParser::IDENT);
    setState(374);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == KsmParser::T__6) {
      setState(370);
      match(KsmParser::T__6);
      setState(371);
      match(KsmParser::IDENT);
      setState(376);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(377);
    match(KsmParser::T__16);
   
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
  enterRule(_localctx, 34, KsmParser::RuleModelVar);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(396);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 41, _ctx)) {
    case 1: {
      enterOuterAlt(_localctx, 1);
      setState(379);
      match(KsmParser::IDENT);
      setState(380);
      match(KsmParser::T__11);
      setState(382);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::IDENT) {
        setState(381);
        dynamic_cast<ModelVarContext *>(_localctx)->index = match(KsmParser::IDENT);
      }
      setState(384);
      match(KsmParser::T__12);
      setState(385);
      match(KsmParser::T__29);
      setState(386);
      typeRef();
      setState(387);
      dynamic_cast<ModelVarContext *>(_localctx)->vmode = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == KsmParser::T__43

      || _la == KsmParser::T__44)) {
        dynamic_cast<ModelVarContext *>(_localctx)->vmode = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(388);
      match(KsmParser::T__1);
      break;
    }

    case 2: {
      enterOuterAlt(_localctx, 2);
      setState(390);
      match(KsmParser::IDENT);
      setState(391);
      match(KsmParser::T__29);
      setState(392);
      typeRef();
      setState(393);
      dynamic_cast<ModelVarContext *>(_localctx)->vmode = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == KsmParser::T__43

      || _la == KsmParser::T__44)) {
        dynamic_cast<ModelVarContext *>(_localctx)->vmode = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(394);
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
  enterRule(_localctx, 36, KsmParser::RulePriorForm);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(421);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__45: {
        enterOuterAlt(_localctx, 1);
        setState(398);
        match(KsmParser::T__45);
        setState(399);
        match(KsmParser::IDENT);
        setState(404);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(400);
          match(KsmParser::T__6);
          setState(401);
          match(KsmParser::IDENT);
          setState(406);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(416);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == KsmParser::T__46) {
          setState(407);
          match(KsmParser::T__46);
          setState(408);
          condition();
          setState(413);
          _errHandler->sync(this);
          _la = _input->LA(1);
          while (_la == KsmParser::T__47) {
            setState(409);
            match(KsmParser::T__47);
            setState(410);
            condition();
            setState(415);
            _errHandler->sync(this);
            _la = _input->LA(1);
          }
        }
        setState(418);
        match(KsmParser::T__29);
        setState(419);
        call();
        break;
      }

      case KsmParser::IDENT: {
        enterOuterAlt(_localctx, 2);
        setState(420);
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
  enterRule(_localctx, 38, KsmParser::RuleCondition);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(434);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 47, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<ConditionContext *>(_tracker.createInstance<KsmParser::ProbConditionContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(423);
      match(KsmParser::IDENT);
      setState(424);
      match(KsmParser::T__15);
      setState(425);
      atom();
      setState(426);
      match(KsmParser::T__16);
      setState(427);
      dynamic_cast<ProbConditionContext *>(_localctx)->op = _input->LT(1);
      _la = _input->LA(1);
      if (!((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__31)
        | (1ULL << KsmParser::T__32)
        | (1ULL << KsmParser::T__48)
        | (1ULL << KsmParser::T__49))) != 0))) {
        dynamic_cast<ProbConditionContext *>(_localctx)->op = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(428);
      number();
      break;
    }

    case 2: {
      _localctx = dynamic_cast<ConditionContext *>(_tracker.createInstance<KsmParser::AtomConditionContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(431);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == KsmParser::T__28) {
        setState(430);
        dynamic_cast<AtomConditionContext *>(_localctx)->neg = match(KsmParser::T__28);
      }
      setState(433);
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
  enterRule(_localctx, 40, KsmParser::RuleKernelParams);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(436);
    match(KsmParser::T__15);
    setState(437);
    kparam();
    setState(442);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == KsmParser::T__6) {
      setState(438);
      match(KsmParser::T__6);
      setState(439);
      kparam();
      setState(444);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(445);
    match(KsmParser::T__16);
   
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
  enterRule(_localctx, 42, KsmParser::RuleKparam);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(447);
    match(KsmParser::IDENT);
    setState(448);
    match(KsmParser::T__29);
    setState(449);
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
  enterRule(_localctx, 44, KsmParser::RuleScheduleRow);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(458);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__11) {
      setState(451);
      match(KsmParser::T__11);
      setState(452);
      dynamic_cast<ScheduleRowContext *>(_localctx)->lo = number();
      setState(453);
      match(KsmParser::T__6);
      setState(454);
      dynamic_cast<ScheduleRowContext *>(_localctx)->hi = rangeEnd();
      setState(455);
      match(KsmParser::T__16);
      setState(456);
      match(KsmParser::T__29);
    }
    setState(460);
    match(KsmParser::T__5);
    setState(469);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::IDENT) {
      setState(461);
      scheduleEntry();
      setState(466);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == KsmParser::T__6) {
        setState(462);
        match(KsmParser::T__6);
        setState(463);
        scheduleEntry();
        setState(468);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
    }
    setState(471);
    match(KsmParser::T__7);
    setState(473);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__1) {
      setState(472);
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
  enterRule(_localctx, 46, KsmParser::RuleRangeEnd);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(477);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case KsmParser::T__53:
      case KsmParser::NUMBER: {
        enterOuterAlt(_localctx, 1);
        setState(475);
        number();
        break;
      }

      case KsmParser::T__50: {
        enterOuterAlt(_localctx, 2);
        setState(476);
        match(KsmParser::T__50);
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
  enterRule(_localctx, 48, KsmParser::RuleScheduleEntry);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(479);
    match(KsmParser::IDENT);
    setState(480);
    match(KsmParser::T__29);
    setState(481);
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
  enterRule(_localctx, 50, KsmParser::RuleCall);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(483);
    qualName();
    setState(496);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__15) {
      setState(484);
      match(KsmParser::T__15);
      setState(493);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__5)
        | (1ULL << KsmParser::T__11)
        | (1ULL << KsmParser::T__50)
        | (1ULL << KsmParser::T__51)
        | (1ULL << KsmParser::T__52)
        | (1ULL << KsmParser::T__53)
        | (1ULL << KsmParser::NUMBER)
        | (1ULL << KsmParser::IDENT)
        | (1ULL << KsmParser::STRING))) != 0)) {
        setState(485);
        arg();
        setState(490);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(486);
          match(KsmParser::T__6);
          setState(487);
          arg();
          setState(492);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(495);
      match(KsmParser::T__16);
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
  enterRule(_localctx, 52, KsmParser::RuleArg);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(500);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 57, _ctx)) {
    case 1: {
      setState(498);
      match(KsmParser::IDENT);
      setState(499);
      match(KsmParser::T__4);
      break;
    }

    }
    setState(502);
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
  enterRule(_localctx, 54, KsmParser::RuleExpr);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(551);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 64, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::NumberExprContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(504);
      number();
      break;
    }

    case 2: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::StringExprContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(505);
      match(KsmParser::STRING);
      break;
    }

    case 3: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::BoolExprContext>(_localctx));
      enterOuterAlt(_localctx, 3);
      setState(506);
      _la = _input->LA(1);
      if (!(_la == KsmParser::T__51

      || _la == KsmParser::T__52)) {
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
      setState(507);
      match(KsmParser::T__50);
      break;
    }

    case 5: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::IndexExprContext>(_localctx));
      enterOuterAlt(_localctx, 5);
      setState(508);
      match(KsmParser::IDENT);
      setState(509);
      match(KsmParser::T__11);
      setState(510);
      match(KsmParser::IDENT);
      setState(511);
      match(KsmParser::T__12);
      break;
    }

    case 6: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::CallExprContext>(_localctx));
      enterOuterAlt(_localctx, 6);
      setState(512);
      qualName();
      setState(513);
      match(KsmParser::T__15);
      setState(522);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__5)
        | (1ULL << KsmParser::T__11)
        | (1ULL << KsmParser::T__50)
        | (1ULL << KsmParser::T__51)
        | (1ULL << KsmParser::T__52)
        | (1ULL << KsmParser::T__53)
        | (1ULL << KsmParser::NUMBER)
        | (1ULL << KsmParser::IDENT)
        | (1ULL << KsmParser::STRING))) != 0)) {
        setState(514);
        arg();
        setState(519);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(515);
          match(KsmParser::T__6);
          setState(516);
          arg();
          setState(521);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(524);
      match(KsmParser::T__16);
      break;
    }

    case 7: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::NameExprContext>(_localctx));
      enterOuterAlt(_localctx, 7);
      setState(526);
      match(KsmParser::IDENT);
      break;
    }

    case 8: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::ListExprContext>(_localctx));
      enterOuterAlt(_localctx, 8);
      setState(527);
      match(KsmParser::T__11);
      setState(536);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__5)
        | (1ULL << KsmParser::T__11)
        | (1ULL << KsmParser::T__50)
        | (1ULL << KsmParser::T__51)
        | (1ULL << KsmParser::T__52)
        | (1ULL << KsmParser::T__53)
        | (1ULL << KsmParser::NUMBER)
        | (1ULL << KsmParser::IDENT)
        | (1ULL << KsmParser::STRING))) != 0)) {
        setState(528);
        expr();
        setState(533);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(529);
          match(KsmParser::T__6);
          setState(530);
          expr();
          setState(535);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(538);
      match(KsmParser::T__12);
      break;
    }

    case 9: {
      _localctx = dynamic_cast<ExprContext *>(_tracker.createInstance<KsmParser::SetExprContext>(_localctx));
      enterOuterAlt(_localctx, 9);
      setState(539);
      match(KsmParser::T__5);
      setState(548);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << KsmParser::T__5)
        | (1ULL << KsmParser::T__11)
        | (1ULL << KsmParser::T__50)
        | (1ULL << KsmParser::T__51)
        | (1ULL << KsmParser::T__52)
        | (1ULL << KsmParser::T__53)
        | (1ULL << KsmParser::NUMBER)
        | (1ULL << KsmParser::IDENT)
        | (1ULL << KsmParser::STRING))) != 0)) {
        setState(540);
        expr();
        setState(545);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == KsmParser::T__6) {
          setState(541);
          match(KsmParser::T__6);
          setState(542);
          expr();
          setState(547);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(550);
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
  enterRule(_localctx, 56, KsmParser::RuleNumber);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(554);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::T__53) {
      setState(553);
      match(KsmParser::T__53);
    }
    setState(556);
    match(KsmParser::NUMBER);
    setState(558);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == KsmParser::IDENT) {
      setState(557);
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
  "param", "typeRef", "ruleHead", "ruleBody", "formula", "implication", 
  "disjunction", "conjunction", "unary", "atom", "modelVar", "priorForm", 
  "condition", "kernelParams", "kparam", "scheduleRow", "rangeEnd", "scheduleEntry", 
  "call", "arg", "expr", "number"
};

std::vector<std::string> KsmParser::_literalNames = {
  "", "'domain'", "';'", "'include'", "'type'", "'='", "'{'", "','", "'}'", 
  "'evidence'", "'query'", "'quantity'", "'['", "']'", "'value'", "'extern'", 
  "'('", "')'", "'->'", "'.'", "'model'", "'extract'", "'prior'", "'likelihood'", 
  "'kernel'", "'pair'", "'/'", "'reverse'", "'schedule'", "'!'", "':'", 
  "'set'", "'<'", "'>'", "'hard'", "'prob'", "'exactly'", "'one'", "'of'", 
  "'<=>'", "'=>'", "'v'", "'^'", "'exists'", "'fixed'", "'sampled'", "'for'", 
  "'where'", "'and'", "'>='", "'<='", "'inf'", "'true'", "'false'", "'-'"
};

std::vector<std::string> KsmParser::_symbolicNames = {
  "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", 
  "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", 
  "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", 
  "", "NUMBER", "IDENT", "STRING", "LINE_COMMENT", "BLOCK_COMMENT", "WS", 
  "ERRCHAR"
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
    0x3, 0x3f, 0x233, 0x4, 0x2, 0x9, 0x2, 0x4, 0x3, 0x9, 0x3, 0x4, 0x4, 
    0x9, 0x4, 0x4, 0x5, 0x9, 0x5, 0x4, 0x6, 0x9, 0x6, 0x4, 0x7, 0x9, 0x7, 
    0x4, 0x8, 0x9, 0x8, 0x4, 0x9, 0x9, 0x9, 0x4, 0xa, 0x9, 0xa, 0x4, 0xb, 
    0x9, 0xb, 0x4, 0xc, 0x9, 0xc, 0x4, 0xd, 0x9, 0xd, 0x4, 0xe, 0x9, 0xe, 
    0x4, 0xf, 0x9, 0xf, 0x4, 0x10, 0x9, 0x10, 0x4, 0x11, 0x9, 0x11, 0x4, 
    0x12, 0x9, 0x12, 0x4, 0x13, 0x9, 0x13, 0x4, 0x14, 0x9, 0x14, 0x4, 0x15, 
    0x9, 0x15, 0x4, 0x16, 0x9, 0x16, 0x4, 0x17, 0x9, 0x17, 0x4, 0x18, 0x9, 
    0x18, 0x4, 0x19, 0x9, 0x19, 0x4, 0x1a, 0x9, 0x1a, 0x4, 0x1b, 0x9, 0x1b, 
    0x4, 0x1c, 0x9, 0x1c, 0x4, 0x1d, 0x9, 0x1d, 0x4, 0x1e, 0x9, 0x1e, 0x3, 
    0x2, 0x7, 0x2, 0x3e, 0xa, 0x2, 0xc, 0x2, 0xe, 0x2, 0x41, 0xb, 0x2, 0x3, 
    0x2, 0x3, 0x2, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x7, 0x3, 0x52, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0x55, 0xb, 0x3, 0x3, 
    0x3, 0x5, 0x3, 0x58, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x7, 0x3, 0x5f, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0x62, 0xb, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x7, 0x3, 0x6c, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0x6f, 0xb, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0x73, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0x7a, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 
    0x7d, 0xb, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0x87, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 
    0x8a, 0xb, 0x3, 0x5, 0x3, 0x8c, 0xa, 0x3, 0x3, 0x3, 0x5, 0x3, 0x8f, 
    0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0x93, 0xa, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x7, 0x3, 0x9f, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0xa2, 0xb, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x5, 0x3, 0xb9, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x7, 0x3, 0xbf, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0xc2, 0xb, 0x3, 0x5, 0x3, 
    0xc4, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0xca, 
    0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0xce, 0xa, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0xd4, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 
    0xd7, 0xb, 0x3, 0x5, 0x3, 0xd9, 0xa, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x7, 0x3, 0xdf, 0xa, 0x3, 0xc, 0x3, 0xe, 0x3, 0xe2, 0xb, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x7, 0x3, 0xe7, 0xa, 0x3, 0xc, 0x3, 0xe, 
    0x3, 0xea, 0xb, 0x3, 0x5, 0x3, 0xec, 0xa, 0x3, 0x3, 0x3, 0x5, 0x3, 0xef, 
    0xa, 0x3, 0x3, 0x4, 0x3, 0x4, 0x3, 0x5, 0x3, 0x5, 0x3, 0x5, 0x3, 0x5, 
    0x3, 0x5, 0x7, 0x5, 0xf8, 0xa, 0x5, 0xc, 0x5, 0xe, 0x5, 0xfb, 0xb, 0x5, 
    0x3, 0x5, 0x3, 0x5, 0x3, 0x6, 0x3, 0x6, 0x5, 0x6, 0x101, 0xa, 0x6, 0x3, 
    0x7, 0x3, 0x7, 0x3, 0x7, 0x3, 0x7, 0x3, 0x8, 0x3, 0x8, 0x3, 0x8, 0x7, 
    0x8, 0x10a, 0xa, 0x8, 0xc, 0x8, 0xe, 0x8, 0x10d, 0xb, 0x8, 0x3, 0x9, 
    0x3, 0x9, 0x3, 0x9, 0x3, 0x9, 0x3, 0x9, 0x5, 0x9, 0x114, 0xa, 0x9, 0x3, 
    0xa, 0x3, 0xa, 0x3, 0xa, 0x7, 0xa, 0x119, 0xa, 0xa, 0xc, 0xa, 0xe, 0xa, 
    0x11c, 0xb, 0xa, 0x3, 0xa, 0x3, 0xa, 0x3, 0xa, 0x3, 0xa, 0x5, 0xa, 0x122, 
    0xa, 0xa, 0x3, 0xb, 0x5, 0xb, 0x125, 0xa, 0xb, 0x3, 0xb, 0x3, 0xb, 0x3, 
    0xb, 0x3, 0xb, 0x3, 0xb, 0x3, 0xb, 0x3, 0xb, 0x3, 0xb, 0x5, 0xb, 0x12f, 
    0xa, 0xb, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 
    0x6, 0xc, 0x137, 0xa, 0xc, 0xd, 0xc, 0xe, 0xc, 0x138, 0x3, 0xc, 0x5, 
    0xc, 0x13c, 0xa, 0xc, 0x3, 0xd, 0x3, 0xd, 0x3, 0xd, 0x7, 0xd, 0x141, 
    0xa, 0xd, 0xc, 0xd, 0xe, 0xd, 0x144, 0xb, 0xd, 0x3, 0xe, 0x3, 0xe, 0x3, 
    0xe, 0x7, 0xe, 0x149, 0xa, 0xe, 0xc, 0xe, 0xe, 0xe, 0x14c, 0xb, 0xe, 
    0x3, 0xf, 0x3, 0xf, 0x3, 0xf, 0x7, 0xf, 0x151, 0xa, 0xf, 0xc, 0xf, 0xe, 
    0xf, 0x154, 0xb, 0xf, 0x3, 0x10, 0x3, 0x10, 0x3, 0x10, 0x7, 0x10, 0x159, 
    0xa, 0x10, 0xc, 0x10, 0xe, 0x10, 0x15c, 0xb, 0x10, 0x3, 0x11, 0x3, 0x11, 
    0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x7, 0x11, 0x164, 0xa, 0x11, 
    0xc, 0x11, 0xe, 0x11, 0x167, 0xb, 0x11, 0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 
    0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x5, 0x11, 0x170, 0xa, 0x11, 
    0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x7, 0x12, 0x177, 
    0xa, 0x12, 0xc, 0x12, 0xe, 0x12, 0x17a, 0xb, 0x12, 0x3, 0x12, 0x3, 0x12, 
    0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x5, 0x13, 0x181, 0xa, 0x13, 0x3, 0x13, 
    0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 
    0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x5, 0x13, 0x18f, 
    0xa, 0x13, 0x3, 0x14, 0x3, 0x14, 0x3, 0x14, 0x3, 0x14, 0x7, 0x14, 0x195, 
    0xa, 0x14, 0xc, 0x14, 0xe, 0x14, 0x198, 0xb, 0x14, 0x3, 0x14, 0x3, 0x14, 
    0x3, 0x14, 0x3, 0x14, 0x7, 0x14, 0x19e, 0xa, 0x14, 0xc, 0x14, 0xe, 0x14, 
    0x1a1, 0xb, 0x14, 0x5, 0x14, 0x1a3, 0xa, 0x14, 0x3, 0x14, 0x3, 0x14, 
    0x3, 0x14, 0x5, 0x14, 0x1a8, 0xa, 0x14, 0x3, 0x15, 0x3, 0x15, 0x3, 0x15, 
    0x3, 0x15, 0x3, 0x15, 0x3, 0x15, 0x3, 0x15, 0x3, 0x15, 0x5, 0x15, 0x1b2, 
    0xa, 0x15, 0x3, 0x15, 0x5, 0x15, 0x1b5, 0xa, 0x15, 0x3, 0x16, 0x3, 0x16, 
    0x3, 0x16, 0x3, 0x16, 0x7, 0x16, 0x1bb, 0xa, 0x16, 0xc, 0x16, 0xe, 0x16, 
    0x1be, 0xb, 0x16, 0x3, 0x16, 0x3, 0x16, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 
    0x3, 0x17, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 
    0x18, 0x3, 0x18, 0x5, 0x18, 0x1cd, 0xa, 0x18, 0x3, 0x18, 0x3, 0x18, 
    0x3, 0x18, 0x3, 0x18, 0x7, 0x18, 0x1d3, 0xa, 0x18, 0xc, 0x18, 0xe, 0x18, 
    0x1d6, 0xb, 0x18, 0x5, 0x18, 0x1d8, 0xa, 0x18, 0x3, 0x18, 0x3, 0x18, 
    0x5, 0x18, 0x1dc, 0xa, 0x18, 0x3, 0x19, 0x3, 0x19, 0x5, 0x19, 0x1e0, 
    0xa, 0x19, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1b, 0x3, 
    0x1b, 0x3, 0x1b, 0x3, 0x1b, 0x3, 0x1b, 0x7, 0x1b, 0x1eb, 0xa, 0x1b, 
    0xc, 0x1b, 0xe, 0x1b, 0x1ee, 0xb, 0x1b, 0x5, 0x1b, 0x1f0, 0xa, 0x1b, 
    0x3, 0x1b, 0x5, 0x1b, 0x1f3, 0xa, 0x1b, 0x3, 0x1c, 0x3, 0x1c, 0x5, 0x1c, 
    0x1f7, 0xa, 0x1c, 0x3, 0x1c, 0x3, 0x1c, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 
    0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 
    0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x7, 0x1d, 0x208, 0xa, 0x1d, 
    0xc, 0x1d, 0xe, 0x1d, 0x20b, 0xb, 0x1d, 0x5, 0x1d, 0x20d, 0xa, 0x1d, 
    0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 
    0x1d, 0x7, 0x1d, 0x216, 0xa, 0x1d, 0xc, 0x1d, 0xe, 0x1d, 0x219, 0xb, 
    0x1d, 0x5, 0x1d, 0x21b, 0xa, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 0x3, 0x1d, 
    0x3, 0x1d, 0x3, 0x1d, 0x7, 0x1d, 0x222, 0xa, 0x1d, 0xc, 0x1d, 0xe, 0x1d, 
    0x225, 0xb, 0x1d, 0x5, 0x1d, 0x227, 0xa, 0x1d, 0x3, 0x1d, 0x5, 0x1d, 
    0x22a, 0xa, 0x1d, 0x3, 0x1e, 0x5, 0x1e, 0x22d, 0xa, 0x1e, 0x3, 0x1e, 
    0x3, 0x1e, 0x5, 0x1e, 0x231, 0xa, 0x1e, 0x3, 0x1e, 0x2, 0x2, 0x1f, 0x2, 
    0x4, 0x6, 0x8, 0xa, 0xc, 0xe, 0x10, 0x12, 0x14, 0x16, 0x18, 0x1a, 0x1c, 
    0x1e, 0x20, 0x22, 0x24, 0x26, 0x28, 0x2a, 0x2c, 0x2e, 0x30, 0x32, 0x34, 
    0x36, 0x38, 0x3a, 0x2, 0x8, 0x3, 0x2, 0xb, 0xc, 0x4, 0x2, 0x18, 0x1a, 
    0x3a, 0x3a, 0x4, 0x2, 0xb, 0xc, 0x3a, 0x3a, 0x3, 0x2, 0x2e, 0x2f, 0x4, 
    0x2, 0x22, 0x23, 0x33, 0x34, 0x3, 0x2, 0x36, 0x37, 0x2, 0x26f, 0x2, 
    0x3f, 0x3, 0x2, 0x2, 0x2, 0x4, 0xee, 0x3, 0x2, 0x2, 0x2, 0x6, 0xf0, 
    0x3, 0x2, 0x2, 0x2, 0x8, 0xf2, 0x3, 0x2, 0x2, 0x2, 0xa, 0xfe, 0x3, 0x2, 
    0x2, 0x2, 0xc, 0x102, 0x3, 0x2, 0x2, 0x2, 0xe, 0x106, 0x3, 0x2, 0x2, 
    0x2, 0x10, 0x10e, 0x3, 0x2, 0x2, 0x2, 0x12, 0x121, 0x3, 0x2, 0x2, 0x2, 
    0x14, 0x124, 0x3, 0x2, 0x2, 0x2, 0x16, 0x13b, 0x3, 0x2, 0x2, 0x2, 0x18, 
    0x13d, 0x3, 0x2, 0x2, 0x2, 0x1a, 0x145, 0x3, 0x2, 0x2, 0x2, 0x1c, 0x14d, 
    0x3, 0x2, 0x2, 0x2, 0x1e, 0x155, 0x3, 0x2, 0x2, 0x2, 0x20, 0x16f, 0x3, 
    0x2, 0x2, 0x2, 0x22, 0x171, 0x3, 0x2, 0x2, 0x2, 0x24, 0x18e, 0x3, 0x2, 
    0x2, 0x2, 0x26, 0x1a7, 0x3, 0x2, 0x2, 0x2, 0x28, 0x1b4, 0x3, 0x2, 0x2, 
    0x2, 0x2a, 0x1b6, 0x3, 0x2, 0x2, 0x2, 0x2c, 0x1c1, 0x3, 0x2, 0x2, 0x2, 
    0x2e, 0x1cc, 0x3, 0x2, 0x2, 0x2, 0x30, 0x1df, 0x3, 0x2, 0x2, 0x2, 0x32, 
    0x1e1, 0x3, 0x2, 0x2, 0x2, 0x34, 0x1e5, 0x3, 0x2, 0x2, 0x2, 0x36, 0x1f6, 
    0x3, 0x2, 0x2, 0x2, 0x38, 0x229, 0x3, 0x2, 0x2, 0x2, 0x3a, 0x22c, 0x3, 
    0x2, 0x2, 0x2, 0x3c, 0x3e, 0x5, 0x4, 0x3, 0x2, 0x3d, 0x3c, 0x3, 0x2, 
    0x2, 0x2, 0x3e, 0x41, 0x3, 0x2, 0x2, 0x2, 0x3f, 0x3d, 0x3, 0x2, 0x2, 
    0x2, 0x3f, 0x40, 0x3, 0x2, 0x2, 0x2, 0x40, 0x42, 0x3, 0x2, 0x2, 0x2, 
    0x41, 0x3f, 0x3, 0x2, 0x2, 0x2, 0x42, 0x43, 0x7, 0x2, 0x2, 0x3, 0x43, 
    0x3, 0x3, 0x2, 0x2, 0x2, 0x44, 0x45, 0x7, 0x3, 0x2, 0x2, 0x45, 0x46, 
    0x7, 0x3a, 0x2, 0x2, 0x46, 0xef, 0x7, 0x4, 0x2, 0x2, 0x47, 0x48, 0x7, 
    0x5, 0x2, 0x2, 0x48, 0x49, 0x7, 0x3b, 0x2, 0x2, 0x49, 0xef, 0x7, 0x4, 
    0x2, 0x2, 0x4a, 0x4b, 0x7, 0x6, 0x2, 0x2, 0x4b, 0x57, 0x7, 0x3a, 0x2, 
    0x2, 0x4c, 0x4d, 0x7, 0x7, 0x2, 0x2, 0x4d, 0x4e, 0x7, 0x8, 0x2, 0x2, 
    0x4e, 0x53, 0x7, 0x3a, 0x2, 0x2, 0x4f, 0x50, 0x7, 0x9, 0x2, 0x2, 0x50, 
    0x52, 0x7, 0x3a, 0x2, 0x2, 0x51, 0x4f, 0x3, 0x2, 0x2, 0x2, 0x52, 0x55, 
    0x3, 0x2, 0x2, 0x2, 0x53, 0x51, 0x3, 0x2, 0x2, 0x2, 0x53, 0x54, 0x3, 
    0x2, 0x2, 0x2, 0x54, 0x56, 0x3, 0x2, 0x2, 0x2, 0x55, 0x53, 0x3, 0x2, 
    0x2, 0x2, 0x56, 0x58, 0x7, 0xa, 0x2, 0x2, 0x57, 0x4c, 0x3, 0x2, 0x2, 
    0x2, 0x57, 0x58, 0x3, 0x2, 0x2, 0x2, 0x58, 0x59, 0x3, 0x2, 0x2, 0x2, 
    0x59, 0xef, 0x7, 0x4, 0x2, 0x2, 0x5a, 0x5b, 0x9, 0x2, 0x2, 0x2, 0x5b, 
    0x60, 0x5, 0x8, 0x5, 0x2, 0x5c, 0x5d, 0x7, 0x9, 0x2, 0x2, 0x5d, 0x5f, 
    0x5, 0x8, 0x5, 0x2, 0x5e, 0x5c, 0x3, 0x2, 0x2, 0x2, 0x5f, 0x62, 0x3, 
    0x2, 0x2, 0x2, 0x60, 0x5e, 0x3, 0x2, 0x2, 0x2, 0x60, 0x61, 0x3, 0x2, 
    0x2, 0x2, 0x61, 0x63, 0x3, 0x2, 0x2, 0x2, 0x62, 0x60, 0x3, 0x2, 0x2, 
    0x2, 0x63, 0x64, 0x7, 0x4, 0x2, 0x2, 0x64, 0xef, 0x3, 0x2, 0x2, 0x2, 
    0x65, 0x66, 0x7, 0xd, 0x2, 0x2, 0x66, 0x72, 0x7, 0x3a, 0x2, 0x2, 0x67, 
    0x68, 0x7, 0xe, 0x2, 0x2, 0x68, 0x6d, 0x5, 0xc, 0x7, 0x2, 0x69, 0x6a, 
    0x7, 0x9, 0x2, 0x2, 0x6a, 0x6c, 0x5, 0xc, 0x7, 0x2, 0x6b, 0x69, 0x3, 
    0x2, 0x2, 0x2, 0x6c, 0x6f, 0x3, 0x2, 0x2, 0x2, 0x6d, 0x6b, 0x3, 0x2, 
    0x2, 0x2, 0x6d, 0x6e, 0x3, 0x2, 0x2, 0x2, 0x6e, 0x70, 0x3, 0x2, 0x2, 
    0x2, 0x6f, 0x6d, 0x3, 0x2, 0x2, 0x2, 0x70, 0x71, 0x7, 0xf, 0x2, 0x2, 
    0x71, 0x73, 0x3, 0x2, 0x2, 0x2, 0x72, 0x67, 0x3, 0x2, 0x2, 0x2, 0x72, 
    0x73, 0x3, 0x2, 0x2, 0x2, 0x73, 0x74, 0x3, 0x2, 0x2, 0x2, 0x74, 0xef, 
    0x7, 0x4, 0x2, 0x2, 0x75, 0x76, 0x7, 0x10, 0x2, 0x2, 0x76, 0x7b, 0x7, 
    0x3a, 0x2, 0x2, 0x77, 0x78, 0x7, 0x9, 0x2, 0x2, 0x78, 0x7a, 0x7, 0x3a, 
    0x2, 0x2, 0x79, 0x77, 0x3, 0x2, 0x2, 0x2, 0x7a, 0x7d, 0x3, 0x2, 0x2, 
    0x2, 0x7b, 0x79, 0x3, 0x2, 0x2, 0x2, 0x7b, 0x7c, 0x3, 0x2, 0x2, 0x2, 
    0x7c, 0x7e, 0x3, 0x2, 0x2, 0x2, 0x7d, 0x7b, 0x3, 0x2, 0x2, 0x2, 0x7e, 
    0xef, 0x7, 0x4, 0x2, 0x2, 0x7f, 0x80, 0x7, 0x11, 0x2, 0x2, 0x80, 0x81, 
    0x5, 0x6, 0x4, 0x2, 0x81, 0x8e, 0x5, 0xe, 0x8, 0x2, 0x82, 0x8b, 0x7, 
    0x12, 0x2, 0x2, 0x83, 0x88, 0x5, 0x10, 0x9, 0x2, 0x84, 0x85, 0x7, 0x9, 
    0x2, 0x2, 0x85, 0x87, 0x5, 0x10, 0x9, 0x2, 0x86, 0x84, 0x3, 0x2, 0x2, 
    0x2, 0x87, 0x8a, 0x3, 0x2, 0x2, 0x2, 0x88, 0x86, 0x3, 0x2, 0x2, 0x2, 
    0x88, 0x89, 0x3, 0x2, 0x2, 0x2, 0x89, 0x8c, 0x3, 0x2, 0x2, 0x2, 0x8a, 
    0x88, 0x3, 0x2, 0x2, 0x2, 0x8b, 0x83, 0x3, 0x2, 0x2, 0x2, 0x8b, 0x8c, 
    0x3, 0x2, 0x2, 0x2, 0x8c, 0x8d, 0x3, 0x2, 0x2, 0x2, 0x8d, 0x8f, 0x7, 
    0x13, 0x2, 0x2, 0x8e, 0x82, 0x3, 0x2, 0x2, 0x2, 0x8e, 0x8f, 0x3, 0x2, 
    0x2, 0x2, 0x8f, 0x92, 0x3, 0x2, 0x2, 0x2, 0x90, 0x91, 0x7, 0x14, 0x2, 
    0x2, 0x91, 0x93, 0x5, 0x12, 0xa, 0x2, 0x92, 0x90, 0x3, 0x2, 0x2, 0x2, 
    0x92, 0x93, 0x3, 0x2, 0x2, 0x2, 0x93, 0x94, 0x3, 0x2, 0x2, 0x2, 0x94, 
    0x95, 0x7, 0x4, 0x2, 0x2, 0x95, 0xef, 0x3, 0x2, 0x2, 0x2, 0x96, 0x97, 
    0x5, 0x14, 0xb, 0x2, 0x97, 0x98, 0x5, 0x16, 0xc, 0x2, 0x98, 0x99, 0x7, 
    0x15, 0x2, 0x2, 0x99, 0xef, 0x3, 0x2, 0x2, 0x2, 0x9a, 0x9b, 0x7, 0x16, 
    0x2, 0x2, 0x9b, 0x9c, 0x7, 0x3a, 0x2, 0x2, 0x9c, 0xa0, 0x7, 0x8, 0x2, 
    0x2, 0x9d, 0x9f, 0x5, 0x24, 0x13, 0x2, 0x9e, 0x9d, 0x3, 0x2, 0x2, 0x2, 
    0x9f, 0xa2, 0x3, 0x2, 0x2, 0x2, 0xa0, 0x9e, 0x3, 0x2, 0x2, 0x2, 0xa0, 
    0xa1, 0x3, 0x2, 0x2, 0x2, 0xa1, 0xa3, 0x3, 0x2, 0x2, 0x2, 0xa2, 0xa0, 
    0x3, 0x2, 0x2, 0x2, 0xa3, 0xef, 0x7, 0xa, 0x2, 0x2, 0xa4, 0xa5, 0x7, 
    0x17, 0x2, 0x2, 0xa5, 0xa6, 0x5, 0x22, 0x12, 0x2, 0xa6, 0xa7, 0x7, 0x7, 
    0x2, 0x2, 0xa7, 0xa8, 0x5, 0x34, 0x1b, 0x2, 0xa8, 0xa9, 0x7, 0x4, 0x2, 
    0x2, 0xa9, 0xef, 0x3, 0x2, 0x2, 0x2, 0xaa, 0xab, 0x7, 0x18, 0x2, 0x2, 
    0xab, 0xac, 0x5, 0x26, 0x14, 0x2, 0xac, 0xad, 0x7, 0x4, 0x2, 0x2, 0xad, 
    0xef, 0x3, 0x2, 0x2, 0x2, 0xae, 0xaf, 0x7, 0x19, 0x2, 0x2, 0xaf, 0xb0, 
    0x5, 0x34, 0x1b, 0x2, 0xb0, 0xb1, 0x7, 0x4, 0x2, 0x2, 0xb1, 0xef, 0x3, 
    0x2, 0x2, 0x2, 0xb2, 0xb3, 0x7, 0x1a, 0x2, 0x2, 0xb3, 0xb4, 0x7, 0x1b, 
    0x2, 0x2, 0xb4, 0xb5, 0x7, 0x3a, 0x2, 0x2, 0xb5, 0xb6, 0x7, 0x1c, 0x2, 
    0x2, 0xb6, 0xb8, 0x7, 0x3a, 0x2, 0x2, 0xb7, 0xb9, 0x5, 0x2a, 0x16, 0x2, 
    0xb8, 0xb7, 0x3, 0x2, 0x2, 0x2, 0xb8, 0xb9, 0x3, 0x2, 0x2, 0x2, 0xb9, 
    0xc3, 0x3, 0x2, 0x2, 0x2, 0xba, 0xbb, 0x7, 0x7, 0x2, 0x2, 0xbb, 0xc0, 
    0x5, 0x34, 0x1b, 0x2, 0xbc, 0xbd, 0x7, 0x9, 0x2, 0x2, 0xbd, 0xbf, 0x5, 
    0x34, 0x1b, 0x2, 0xbe, 0xbc, 0x3, 0x2, 0x2, 0x2, 0xbf, 0xc2, 0x3, 0x2, 
    0x2, 0x2, 0xc0, 0xbe, 0x3, 0x2, 0x2, 0x2, 0xc0, 0xc1, 0x3, 0x2, 0x2, 
    0x2, 0xc1, 0xc4, 0x3, 0x2, 0x2, 0x2, 0xc2, 0xc0, 0x3, 0x2, 0x2, 0x2, 
    0xc3, 0xba, 0x3, 0x2, 0x2, 0x2, 0xc3, 0xc4, 0x3, 0x2, 0x2, 0x2, 0xc4, 
    0xc5, 0x3, 0x2, 0x2, 0x2, 0xc5, 0xef, 0x7, 0x4, 0x2, 0x2, 0xc6, 0xc7, 
    0x7, 0x1a, 0x2, 0x2, 0xc7, 0xc9, 0x7, 0x3a, 0x2, 0x2, 0xc8, 0xca, 0x5, 
    0x2a, 0x16, 0x2, 0xc9, 0xc8, 0x3, 0x2, 0x2, 0x2, 0xc9, 0xca, 0x3, 0x2, 
    0x2, 0x2, 0xca, 0xcd, 0x3, 0x2, 0x2, 0x2, 0xcb, 0xcc, 0x7, 0x1d, 0x2, 
    0x2, 0xcc, 0xce, 0x7, 0x3a, 0x2, 0x2, 0xcd, 0xcb, 0x3, 0x2, 0x2, 0x2, 
    0xcd, 0xce, 0x3, 0x2, 0x2, 0x2, 0xce, 0xd8, 0x3, 0x2, 0x2, 0x2, 0xcf, 
    0xd0, 0x7, 0x7, 0x2, 0x2, 0xd0, 0xd5, 0x5, 0x34, 0x1b, 0x2, 0xd1, 0xd2, 
    0x7, 0x9, 0x2, 0x2, 0xd2, 0xd4, 0x5, 0x34, 0x1b, 0x2, 0xd3, 0xd1, 0x3, 
    0x2, 0x2, 0x2, 0xd4, 0xd7, 0x3, 0x2, 0x2, 0x2, 0xd5, 0xd3, 0x3, 0x2, 
    0x2, 0x2, 0xd5, 0xd6, 0x3, 0x2, 0x2, 0x2, 0xd6, 0xd9, 0x3, 0x2, 0x2, 
    0x2, 0xd7, 0xd5, 0x3, 0x2, 0x2, 0x2, 0xd8, 0xcf, 0x3, 0x2, 0x2, 0x2, 
    0xd8, 0xd9, 0x3, 0x2, 0x2, 0x2, 0xd9, 0xda, 0x3, 0x2, 0x2, 0x2, 0xda, 
    0xef, 0x7, 0x4, 0x2, 0x2, 0xdb, 0xdc, 0x7, 0x1e, 0x2, 0x2, 0xdc, 0xeb, 
    0x7, 0x8, 0x2, 0x2, 0xdd, 0xdf, 0x5, 0x2e, 0x18, 0x2, 0xde, 0xdd, 0x3, 
    0x2, 0x2, 0x2, 0xdf, 0xe2, 0x3, 0x2, 0x2, 0x2, 0xe0, 0xde, 0x3, 0x2, 
    0x2, 0x2, 0xe0, 0xe1, 0x3, 0x2, 0x2, 0x2, 0xe1, 0xec, 0x3, 0x2, 0x2, 
    0x2, 0xe2, 0xe0, 0x3, 0x2, 0x2, 0x2, 0xe3, 0xe8, 0x5, 0x32, 0x1a, 0x2, 
    0xe4, 0xe5, 0x7, 0x9, 0x2, 0x2, 0xe5, 0xe7, 0x5, 0x32, 0x1a, 0x2, 0xe6, 
    0xe4, 0x3, 0x2, 0x2, 0x2, 0xe7, 0xea, 0x3, 0x2, 0x2, 0x2, 0xe8, 0xe6, 
    0x3, 0x2, 0x2, 0x2, 0xe8, 0xe9, 0x3, 0x2, 0x2, 0x2, 0xe9, 0xec, 0x3, 
    0x2, 0x2, 0x2, 0xea, 0xe8, 0x3, 0x2, 0x2, 0x2, 0xeb, 0xe0, 0x3, 0x2, 
    0x2, 0x2, 0xeb, 0xe3, 0x3, 0x2, 0x2, 0x2, 0xec, 0xed, 0x3, 0x2, 0x2, 
    0x2, 0xed, 0xef, 0x7, 0xa, 0x2, 0x2, 0xee, 0x44, 0x3, 0x2, 0x2, 0x2, 
    0xee, 0x47, 0x3, 0x2, 0x2, 0x2, 0xee, 0x4a, 0x3, 0x2, 0x2, 0x2, 0xee, 
    0x5a, 0x3, 0x2, 0x2, 0x2, 0xee, 0x65, 0x3, 0x2, 0x2, 0x2, 0xee, 0x75, 
    0x3, 0x2, 0x2, 0x2, 0xee, 0x7f, 0x3, 0x2, 0x2, 0x2, 0xee, 0x96, 0x3, 
    0x2, 0x2, 0x2, 0xee, 0x9a, 0x3, 0x2, 0x2, 0x2, 0xee, 0xa4, 0x3, 0x2, 
    0x2, 0x2, 0xee, 0xaa, 0x3, 0x2, 0x2, 0x2, 0xee, 0xae, 0x3, 0x2, 0x2, 
    0x2, 0xee, 0xb2, 0x3, 0x2, 0x2, 0x2, 0xee, 0xc6, 0x3, 0x2, 0x2, 0x2, 
    0xee, 0xdb, 0x3, 0x2, 0x2, 0x2, 0xef, 0x5, 0x3, 0x2, 0x2, 0x2, 0xf0, 
    0xf1, 0x9, 0x3, 0x2, 0x2, 0xf1, 0x7, 0x3, 0x2, 0x2, 0x2, 0xf2, 0xf3, 
    0x7, 0x3a, 0x2, 0x2, 0xf3, 0xf4, 0x7, 0x12, 0x2, 0x2, 0xf4, 0xf9, 0x5, 
    0xa, 0x6, 0x2, 0xf5, 0xf6, 0x7, 0x9, 0x2, 0x2, 0xf6, 0xf8, 0x5, 0xa, 
    0x6, 0x2, 0xf7, 0xf5, 0x3, 0x2, 0x2, 0x2, 0xf8, 0xfb, 0x3, 0x2, 0x2, 
    0x2, 0xf9, 0xf7, 0x3, 0x2, 0x2, 0x2, 0xf9, 0xfa, 0x3, 0x2, 0x2, 0x2, 
    0xfa, 0xfc, 0x3, 0x2, 0x2, 0x2, 0xfb, 0xf9, 0x3, 0x2, 0x2, 0x2, 0xfc, 
    0xfd, 0x7, 0x13, 0x2, 0x2, 0xfd, 0x9, 0x3, 0x2, 0x2, 0x2, 0xfe, 0x100, 
    0x7, 0x3a, 0x2, 0x2, 0xff, 0x101, 0x7, 0x1f, 0x2, 0x2, 0x100, 0xff, 
    0x3, 0x2, 0x2, 0x2, 0x100, 0x101, 0x3, 0x2, 0x2, 0x2, 0x101, 0xb, 0x3, 
    0x2, 0x2, 0x2, 0x102, 0x103, 0x7, 0x3a, 0x2, 0x2, 0x103, 0x104, 0x7, 
    0x7, 0x2, 0x2, 0x104, 0x105, 0x5, 0x3a, 0x1e, 0x2, 0x105, 0xd, 0x3, 
    0x2, 0x2, 0x2, 0x106, 0x10b, 0x7, 0x3a, 0x2, 0x2, 0x107, 0x108, 0x7, 
    0x15, 0x2, 0x2, 0x108, 0x10a, 0x7, 0x3a, 0x2, 0x2, 0x109, 0x107, 0x3, 
    0x2, 0x2, 0x2, 0x10a, 0x10d, 0x3, 0x2, 0x2, 0x2, 0x10b, 0x109, 0x3, 
    0x2, 0x2, 0x2, 0x10b, 0x10c, 0x3, 0x2, 0x2, 0x2, 0x10c, 0xf, 0x3, 0x2, 
    0x2, 0x2, 0x10d, 0x10b, 0x3, 0x2, 0x2, 0x2, 0x10e, 0x10f, 0x7, 0x3a, 
    0x2, 0x2, 0x10f, 0x110, 0x7, 0x20, 0x2, 0x2, 0x110, 0x113, 0x5, 0x12, 
    0xa, 0x2, 0x111, 0x112, 0x7, 0x7, 0x2, 0x2, 0x112, 0x114, 0x5, 0x38, 
    0x1d, 0x2, 0x113, 0x111, 0x3, 0x2, 0x2, 0x2, 0x113, 0x114, 0x3, 0x2, 
    0x2, 0x2, 0x114, 0x11, 0x3, 0x2, 0x2, 0x2, 0x115, 0x11a, 0x7, 0x3a, 
    0x2, 0x2, 0x116, 0x117, 0x7, 0xe, 0x2, 0x2, 0x117, 0x119, 0x7, 0xf, 
    0x2, 0x2, 0x118, 0x116, 0x3, 0x2, 0x2, 0x2, 0x119, 0x11c, 0x3, 0x2, 
    0x2, 0x2, 0x11a, 0x118, 0x3, 0x2, 0x2, 0x2, 0x11a, 0x11b, 0x3, 0x2, 
    0x2, 0x2, 0x11b, 0x122, 0x3, 0x2, 0x2, 0x2, 0x11c, 0x11a, 0x3, 0x2, 
    0x2, 0x2, 0x11d, 0x11e, 0x7, 0x21, 0x2, 0x2, 0x11e, 0x11f, 0x7, 0x22, 
    0x2, 0x2, 0x11f, 0x120, 0x9, 0x4, 0x2, 0x2, 0x120, 0x122, 0x7, 0x23, 
    0x2, 0x2, 0x121, 0x115, 0x3, 0x2, 0x2, 0x2, 0x121, 0x11d, 0x3, 0x2, 
    0x2, 0x2, 0x122, 0x13, 0x3, 0x2, 0x2, 0x2, 0x123, 0x125, 0x7, 0x24, 
    0x2, 0x2, 0x124, 0x123, 0x3, 0x2, 0x2, 0x2, 0x124, 0x125, 0x3, 0x2, 
    0x2, 0x2, 0x125, 0x12e, 0x3, 0x2, 0x2, 0x2, 0x126, 0x127, 0x7, 0x25, 
    0x2, 0x2, 0x127, 0x128, 0x5, 0x3a, 0x1e, 0x2, 0x128, 0x129, 0x7, 0x20, 
    0x2, 0x2, 0x129, 0x12f, 0x3, 0x2, 0x2, 0x2, 0x12a, 0x12b, 0x7, 0x3a, 
    0x2, 0x2, 0x12b, 0x12c, 0x5, 0x3a, 0x1e, 0x2, 0x12c, 0x12d, 0x7, 0x20, 
    0x2, 0x2, 0x12d, 0x12f, 0x3, 0x2, 0x2, 0x2, 0x12e, 0x126, 0x3, 0x2, 
    0x2, 0x2, 0x12e, 0x12a, 0x3, 0x2, 0x2, 0x2, 0x12e, 0x12f, 0x3, 0x2, 
    0x2, 0x2, 0x12f, 0x15, 0x3, 0x2, 0x2, 0x2, 0x130, 0x131, 0x7, 0x26, 
    0x2, 0x2, 0x131, 0x132, 0x7, 0x27, 0x2, 0x2, 0x132, 0x133, 0x7, 0x28, 
    0x2, 0x2, 0x133, 0x136, 0x5, 0x22, 0x12, 0x2, 0x134, 0x135, 0x7, 0x9, 
    0x2, 0x2, 0x135, 0x137, 0x5, 0x22, 0x12, 0x2, 0x136, 0x134, 0x3, 0x2, 
    0x2, 0x2, 0x137, 0x138, 0x3, 0x2, 0x2, 0x2, 0x138, 0x136, 0x3, 0x2, 
    0x2, 0x2, 0x138, 0x139, 0x3, 0x2, 0x2, 0x2, 0x139, 0x13c, 0x3, 0x2, 
    0x2, 0x2, 0x13a, 0x13c, 0x5, 0x18, 0xd, 0x2, 0x13b, 0x130, 0x3, 0x2, 
    0x2, 0x2, 0x13b, 0x13a, 0x3, 0x2, 0x2, 0x2, 0x13c, 0x17, 0x3, 0x2, 0x2, 
    0x2, 0x13d, 0x142, 0x5, 0x1a, 0xe, 0x2, 0x13e, 0x13f, 0x7, 0x29, 0x2, 
    0x2, 0x13f, 0x141, 0x5, 0x1a, 0xe, 0x2, 0x140, 0x13e, 0x3, 0x2, 0x2, 
    0x2, 0x141, 0x144, 0x3, 0x2, 0x2, 0x2, 0x142, 0x140, 0x3, 0x2, 0x2, 
    0x2, 0x142, 0x143, 0x3, 0x2, 0x2, 0x2, 0x143, 0x19, 0x3, 0x2, 0x2, 0x2, 
    0x144, 0x142, 0x3, 0x2, 0x2, 0x2, 0x145, 0x14a, 0x5, 0x1c, 0xf, 0x2, 
    0x146, 0x147, 0x7, 0x2a, 0x2, 0x2, 0x147, 0x149, 0x5, 0x1c, 0xf, 0x2, 
    0x148, 0x146, 0x3, 0x2, 0x2, 0x2, 0x149, 0x14c, 0x3, 0x2, 0x2, 0x2, 
    0x14a, 0x148, 0x3, 0x2, 0x2, 0x2, 0x14a, 0x14b, 0x3, 0x2, 0x2, 0x2, 
    0x14b, 0x1b, 0x3, 0x2, 0x2, 0x2, 0x14c, 0x14a, 0x3, 0x2, 0x2, 0x2, 0x14d, 
    0x152, 0x5, 0x1e, 0x10, 0x2, 0x14e, 0x14f, 0x7, 0x2b, 0x2, 0x2, 0x14f, 
    0x151, 0x5, 0x1e, 0x10, 0x2, 0x150, 0x14e, 0x3, 0x2, 0x2, 0x2, 0x151, 
    0x154, 0x3, 0x2, 0x2, 0x2, 0x152, 0x150, 0x3, 0x2, 0x2, 0x2, 0x152, 
    0x153, 0x3, 0x2, 0x2, 0x2, 0x153, 0x1d, 0x3, 0x2, 0x2, 0x2, 0x154, 0x152, 
    0x3, 0x2, 0x2, 0x2, 0x155, 0x15a, 0x5, 0x20, 0x11, 0x2, 0x156, 0x157, 
    0x7, 0x2c, 0x2, 0x2, 0x157, 0x159, 0x5, 0x20, 0x11, 0x2, 0x158, 0x156, 
    0x3, 0x2, 0x2, 0x2, 0x159, 0x15c, 0x3, 0x2, 0x2, 0x2, 0x15a, 0x158, 
    0x3, 0x2, 0x2, 0x2, 0x15a, 0x15b, 0x3, 0x2, 0x2, 0x2, 0x15b, 0x1f, 0x3, 
    0x2, 0x2, 0x2, 0x15c, 0x15a, 0x3, 0x2, 0x2, 0x2, 0x15d, 0x15e, 0x7, 
    0x1f, 0x2, 0x2, 0x15e, 0x170, 0x5, 0x20, 0x11, 0x2, 0x15f, 0x160, 0x7, 
    0x2d, 0x2, 0x2, 0x160, 0x165, 0x7, 0x3a, 0x2, 0x2, 0x161, 0x162, 0x7, 
    0x9, 0x2, 0x2, 0x162, 0x164, 0x7, 0x3a, 0x2, 0x2, 0x163, 0x161, 0x3, 
    0x2, 0x2, 0x2, 0x164, 0x167, 0x3, 0x2, 0x2, 0x2, 0x165, 0x163, 0x3, 
    0x2, 0x2, 0x2, 0x165, 0x166, 0x3, 0x2, 0x2, 0x2, 0x166, 0x168, 0x3, 
    0x2, 0x2, 0x2, 0x167, 0x165, 0x3, 0x2, 0x2, 0x2, 0x168, 0x169, 0x7, 
    0x20, 0x2, 0x2, 0x169, 0x170, 0x5, 0x18, 0xd, 0x2, 0x16a, 0x170, 0x5, 
    0x22, 0x12, 0x2, 0x16b, 0x16c, 0x7, 0x12, 0x2, 0x2, 0x16c, 0x16d, 0x5, 
    0x18, 0xd, 0x2, 0x16d, 0x16e, 0x7, 0x13, 0x2, 0x2, 0x16e, 0x170, 0x3, 
    0x2, 0x2, 0x2, 0x16f, 0x15d, 0x3, 0x2, 0x2, 0x2, 0x16f, 0x15f, 0x3, 
    0x2, 0x2, 0x2, 0x16f, 0x16a, 0x3, 0x2, 0x2, 0x2, 0x16f, 0x16b, 0x3, 
    0x2, 0x2, 0x2, 0x170, 0x21, 0x3, 0x2, 0x2, 0x2, 0x171, 0x172, 0x7, 0x3a, 
    0x2, 0x2, 0x172, 0x173, 0x7, 0x12, 0x2, 0x2, 0x173, 0x178, 0x7, 0x3a, 
    0x2, 0x2, 0x174, 0x175, 0x7, 0x9, 0x2, 0x2, 0x175, 0x177, 0x7, 0x3a, 
    0x2, 0x2, 0x176, 0x174, 0x3, 0x2, 0x2, 0x2, 0x177, 0x17a, 0x3, 0x2, 
    0x2, 0x2, 0x178, 0x176, 0x3, 0x2, 0x2, 0x2, 0x178, 0x179, 0x3, 0x2, 
    0x2, 0x2, 0x179, 0x17b, 0x3, 0x2, 0x2, 0x2, 0x17a, 0x178, 0x3, 0x2, 
    0x2, 0x2, 0x17b, 0x17c, 0x7, 0x13, 0x2, 0x2, 0x17c, 0x23, 0x3, 0x2, 
    0x2, 0x2, 0x17d, 0x17e, 0x7, 0x3a, 0x2, 0x2, 0x17e, 0x180, 0x7, 0xe, 
    0x2, 0x2, 0x17f, 0x181, 0x7, 0x3a, 0x2, 0x2, 0x180, 0x17f, 0x3, 0x2, 
    0x2, 0x2, 0x180, 0x181, 0x3, 0x2, 0x2, 0x2, 0x181, 0x182, 0x3, 0x2, 
    0x2, 0x2, 0x182, 0x183, 0x7, 0xf, 0x2, 0x2, 0x183, 0x184, 0x7, 0x20, 
    0x2, 0x2, 0x184, 0x185, 0x5, 0x12, 0xa, 0x2, 0x185, 0x186, 0x9, 0x5, 
    0x2, 0x2, 0x186, 0x187, 0x7, 0x4, 0x2, 0x2, 0x187, 0x18f, 0x3, 0x2, 
    0x2, 0x2, 0x188, 0x189, 0x7, 0x3a, 0x2, 0x2, 0x189, 0x18a, 0x7, 0x20, 
    0x2, 0x2, 0x18a, 0x18b, 0x5, 0x12, 0xa, 0x2, 0x18b, 0x18c, 0x9, 0x5, 
    0x2, 0x2, 0x18c, 0x18d, 0x7, 0x4, 0x2, 0x2, 0x18d, 0x18f, 0x3, 0x2, 
    0x2, 0x2, 0x18e, 0x17d, 0x3, 0x2, 0x2, 0x2, 0x18e, 0x188, 0x3, 0x2, 
    0x2, 0x2, 0x18f, 0x25, 0x3, 0x2, 0x2, 0x2, 0x190, 0x191, 0x7, 0x30, 
    0x2, 0x2, 0x191, 0x196, 0x7, 0x3a, 0x2, 0x2, 0x192, 0x193, 0x7, 0x9, 
    0x2, 0x2, 0x193, 0x195, 0x7, 0x3a, 0x2, 0x2, 0x194, 0x192, 0x3, 0x2, 
    0x2, 0x2, 0x195, 0x198, 0x3, 0x2, 0x2, 0x2, 0x196, 0x194, 0x3, 0x2, 
    0x2, 0x2, 0x196, 0x197, 0x3, 0x2, 0x2, 0x2, 0x197, 0x1a2, 0x3, 0x2, 
    0x2, 0x2, 0x198, 0x196, 0x3, 0x2, 0x2, 0x2, 0x199, 0x19a, 0x7, 0x31, 
    0x2, 0x2, 0x19a, 0x19f, 0x5, 0x28, 0x15, 0x2, 0x19b, 0x19c, 0x7, 0x32, 
    0x2, 0x2, 0x19c, 0x19e, 0x5, 0x28, 0x15, 0x2, 0x19d, 0x19b, 0x3, 0x2, 
    0x2, 0x2, 0x19e, 0x1a1, 0x3, 0x2, 0x2, 0x2, 0x19f, 0x19d, 0x3, 0x2, 
    0x2, 0x2, 0x19f, 0x1a0, 0x3, 0x2, 0x2, 0x2, 0x1a0, 0x1a3, 0x3, 0x2, 
    0x2, 0x2, 0x1a1, 0x19f, 0x3, 0x2, 0x2, 0x2, 0x1a2, 0x199, 0x3, 0x2, 
    0x2, 0x2, 0x1a2, 0x1a3, 0x3, 0x2, 0x2, 0x2, 0x1a3, 0x1a4, 0x3, 0x2, 
    0x2, 0x2, 0x1a4, 0x1a5, 0x7, 0x20, 0x2, 0x2, 0x1a5, 0x1a8, 0x5, 0x34, 
    0x1b, 0x2, 0x1a6, 0x1a8, 0x5, 0x34, 0x1b, 0x2, 0x1a7, 0x190, 0x3, 0x2, 
    0x2, 0x2, 0x1a7, 0x1a6, 0x3, 0x2, 0x2, 0x2, 0x1a8, 0x27, 0x3, 0x2, 0x2, 
    0x2, 0x1a9, 0x1aa, 0x7, 0x3a, 0x2, 0x2, 0x1aa, 0x1ab, 0x7, 0x12, 0x2, 
    0x2, 0x1ab, 0x1ac, 0x5, 0x22, 0x12, 0x2, 0x1ac, 0x1ad, 0x7, 0x13, 0x2, 
    0x2, 0x1ad, 0x1ae, 0x9, 0x6, 0x2, 0x2, 0x1ae, 0x1af, 0x5, 0x3a, 0x1e, 
    0x2, 0x1af, 0x1b5, 0x3, 0x2, 0x2, 0x2, 0x1b0, 0x1b2, 0x7, 0x1f, 0x2, 
    0x2, 0x1b1, 0x1b0, 0x3, 0x2, 0x2, 0x2, 0x1b1, 0x1b2, 0x3, 0x2, 0x2, 
    0x2, 0x1b2, 0x1b3, 0x3, 0x2, 0x2, 0x2, 0x1b3, 0x1b5, 0x5, 0x22, 0x12, 
    0x2, 0x1b4, 0x1a9, 0x3, 0x2, 0x2, 0x2, 0x1b4, 0x1b1, 0x3, 0x2, 0x2, 
    0x2, 0x1b5, 0x29, 0x3, 0x2, 0x2, 0x2, 0x1b6, 0x1b7, 0x7, 0x12, 0x2, 
    0x2, 0x1b7, 0x1bc, 0x5, 0x2c, 0x17, 0x2, 0x1b8, 0x1b9, 0x7, 0x9, 0x2, 
    0x2, 0x1b9, 0x1bb, 0x5, 0x2c, 0x17, 0x2, 0x1ba, 0x1b8, 0x3, 0x2, 0x2, 
    0x2, 0x1bb, 0x1be, 0x3, 0x2, 0x2, 0x2, 0x1bc, 0x1ba, 0x3, 0x2, 0x2, 
    0x2, 0x1bc, 0x1bd, 0x3, 0x2, 0x2, 0x2, 0x1bd, 0x1bf, 0x3, 0x2, 0x2, 
    0x2, 0x1be, 0x1bc, 0x3, 0x2, 0x2, 0x2, 0x1bf, 0x1c0, 0x7, 0x13, 0x2, 
    0x2, 0x1c0, 0x2b, 0x3, 0x2, 0x2, 0x2, 0x1c1, 0x1c2, 0x7, 0x3a, 0x2, 
    0x2, 0x1c2, 0x1c3, 0x7, 0x20, 0x2, 0x2, 0x1c3, 0x1c4, 0x7, 0x3a, 0x2, 
    0x2, 0x1c4, 0x2d, 0x3, 0x2, 0x2, 0x2, 0x1c5, 0x1c6, 0x7, 0xe, 0x2, 0x2, 
    0x1c6, 0x1c7, 0x5, 0x3a, 0x1e, 0x2, 0x1c7, 0x1c8, 0x7, 0x9, 0x2, 0x2, 
    0x1c8, 0x1c9, 0x5, 0x30, 0x19, 0x2, 0x1c9, 0x1ca, 0x7, 0x13, 0x2, 0x2, 
    0x1ca, 0x1cb, 0x7, 0x20, 0x2, 0x2, 0x1cb, 0x1cd, 0x3, 0x2, 0x2, 0x2, 
    0x1cc, 0x1c5, 0x3, 0x2, 0x2, 0x2, 0x1cc, 0x1cd, 0x3, 0x2, 0x2, 0x2, 
    0x1cd, 0x1ce, 0x3, 0x2, 0x2, 0x2, 0x1ce, 0x1d7, 0x7, 0x8, 0x2, 0x2, 
    0x1cf, 0x1d4, 0x5, 0x32, 0x1a, 0x2, 0x1d0, 0x1d1, 0x7, 0x9, 0x2, 0x2, 
    0x1d1, 0x1d3, 0x5, 0x32, 0x1a, 0x2, 0x1d2, 0x1d0, 0x3, 0x2, 0x2, 0x2, 
    0x1d3, 0x1d6, 0x3, 0x2, 0x2, 0x2, 0x1d4, 0x1d2, 0x3, 0x2, 0x2, 0x2, 
    0x1d4, 0x1d5, 0x3, 0x2, 0x2, 0x2, 0x1d5, 0x1d8, 0x3, 0x2, 0x2, 0x2, 
    0x1d6, 0x1d4, 0x3, 0x2, 0x2, 0x2, 0x1d7, 0x1cf, 0x3, 0x2, 0x2, 0x2, 
    0x1d7, 0x1d8, 0x3, 0x2, 0x2, 0x2, 0x1d8, 0x1d9, 0x3, 0x2, 0x2, 0x2, 
    0x1d9, 0x1db, 0x7, 0xa, 0x2, 0x2, 0x1da, 0x1dc, 0x7, 0x4, 0x2, 0x2, 
    0x1db, 0x1da, 0x3, 0x2, 0x2, 0x2, 0x1db, 0x1dc, 0x3, 0x2, 0x2, 0x2, 
    0x1dc, 0x2f, 0x3, 0x2, 0x2, 0x2, 0x1dd, 0x1e0, 0x5, 0x3a, 0x1e, 0x2, 
    0x1de, 0x1e0, 0x7, 0x35, 0x2, 0x2, 0x1df, 0x1dd, 0x3, 0x2, 0x2, 0x2, 
    0x1df, 0x1de, 0x3, 0x2, 0x2, 0x2, 0x1e0, 0x31, 0x3, 0x2, 0x2, 0x2, 0x1e1, 
    0x1e2, 0x7, 0x3a, 0x2, 0x2, 0x1e2, 0x1e3, 0x7, 0x20, 0x2, 0x2, 0x1e3, 
    0x1e4, 0x5, 0x3a, 0x1e, 0x2, 0x1e4, 0x33, 0x3, 0x2, 0x2, 0x2, 0x1e5, 
    0x1f2, 0x5, 0xe, 0x8, 0x2, 0x1e6, 0x1ef, 0x7, 0x12, 0x2, 0x2, 0x1e7, 
    0x1ec, 0x5, 0x36, 0x1c, 0x2, 0x1e8, 0x1e9, 0x7, 0x9, 0x2, 0x2, 0x1e9, 
    0x1eb, 0x5, 0x36, 0x1c, 0x2, 0x1ea, 0x1e8, 0x3, 0x2, 0x2, 0x2, 0x1eb, 
    0x1ee, 0x3, 0x2, 0x2, 0x2, 0x1ec, 0x1ea, 0x3, 0x2, 0x2, 0x2, 0x1ec, 
    0x1ed, 0x3, 0x2, 0x2, 0x2, 0x1ed, 0x1f0, 0x3, 0x2, 0x2, 0x2, 0x1ee, 
    0x1ec, 0x3, 0x2, 0x2, 0x2, 0x1ef, 0x1e7, 0x3, 0x2, 0x2, 0x2, 0x1ef, 
    0x1f0, 0x3, 0x2, 0x2, 0x2, 0x1f0, 0x1f1, 0x3, 0x2, 0x2, 0x2, 0x1f1, 
    0x1f3, 0x7, 0x13, 0x2, 0x2, 0x1f2, 0x1e6, 0x3, 0x2, 0x2, 0x2, 0x1f2, 
    0x1f3, 0x3, 0x2, 0x2, 0x2, 0x1f3, 0x35, 0x3, 0x2, 0x2, 0x2, 0x1f4, 0x1f5, 
    0x7, 0x3a, 0x2, 0x2, 0x1f5, 0x1f7, 0x7, 0x7, 0x2, 0x2, 0x1f6, 0x1f4, 
    0x3, 0x2, 0x2, 0x2, 0x1f6, 0x1f7, 0x3, 0x2, 0x2, 0x2, 0x1f7, 0x1f8, 
    0x3, 0x2, 0x2, 0x2, 0x1f8, 0x1f9, 0x5, 0x38, 0x1d, 0x2, 0x1f9, 0x37, 
    0x3, 0x2, 0x2, 0x2, 0x1fa, 0x22a, 0x5, 0x3a, 0x1e, 0x2, 0x1fb, 0x22a, 
    0x7, 0x3b, 0x2, 0x2, 0x1fc, 0x22a, 0x9, 0x7, 0x2, 0x2, 0x1fd, 0x22a, 
    0x7, 0x35, 0x2, 0x2, 0x1fe, 0x1ff, 0x7, 0x3a, 0x2, 0x2, 0x1ff, 0x200, 
    0x7, 0xe, 0x2, 0x2, 0x200, 0x201, 0x7, 0x3a, 0x2, 0x2, 0x201, 0x22a, 
    0x7, 0xf, 0x2, 0x2, 0x202, 0x203, 0x5, 0xe, 0x8, 0x2, 0x203, 0x20c, 
    0x7, 0x12, 0x2, 0x2, 0x204, 0x209, 0x5, 0x36, 0x1c, 0x2, 0x205, 0x206, 
    0x7, 0x9, 0x2, 0x2, 0x206, 0x208, 0x5, 0x36, 0x1c, 0x2, 0x207, 0x205, 
    0x3, 0x2, 0x2, 0x2, 0x208, 0x20b, 0x3, 0x2, 0x2, 0x2, 0x209, 0x207, 
    0x3, 0x2, 0x2, 0x2, 0x209, 0x20a, 0x3, 0x2, 0x2, 0x2, 0x20a, 0x20d, 
    0x3, 0x2, 0x2, 0x2, 0x20b, 0x209, 0x3, 0x2, 0x2, 0x2, 0x20c, 0x204, 
    0x3, 0x2, 0x2, 0x2, 0x20c, 0x20d, 0x3, 0x2, 0x2, 0x2, 0x20d, 0x20e, 
    0x3, 0x2, 0x2, 0x2, 0x20e, 0x20f, 0x7, 0x13, 0x2, 0x2, 0x20f, 0x22a, 
    0x3, 0x2, 0x2, 0x2, 0x210, 0x22a, 0x7, 0x3a, 0x2, 0x2, 0x211, 0x21a, 
    0x7, 0xe, 0x2, 0x2, 0x212, 0x217, 0x5, 0x38, 0x1d, 0x2, 0x213, 0x214, 
    0x7, 0x9, 0x2, 0x2, 0x214, 0x216, 0x5, 0x38, 0x1d, 0x2, 0x215, 0x213, 
    0x3, 0x2, 0x2, 0x2, 0x216, 0x219, 0x3, 0x2, 0x2, 0x2, 0x217, 0x215, 
    0x3, 0x2, 0x2, 0x2, 0x217, 0x218, 0x3, 0x2, 0x2, 0x2, 0x218, 0x21b, 
    0x3, 0x2, 0x2, 0x2, 0x219, 0x217, 0x3, 0x2, 0x2, 0x2, 0x21a, 0x212, 
    0x3, 0x2, 0x2, 0x2, 0x21a, 0x21b, 0x3, 0x2, 0x2, 0x2, 0x21b, 0x21c, 
    0x3, 0x2, 0x2, 0x2, 0x21c, 0x22a, 0x7, 0xf, 0x2, 0x2, 0x21d, 0x226, 
    0x7, 0x8, 0x2, 0x2, 0x21e, 0x223, 0x5, 0x38, 0x1d, 0x2, 0x21f, 0x220, 
    0x7, 0x9, 0x2, 0x2, 0x220, 0x222, 0x5, 0x38, 0x1d, 0x2, 0x221, 0x21f, 
    0x3, 0x2, 0x2, 0x2, 0x222, 0x225, 0x3, 0x2, 0x2, 0x2, 0x223, 0x221, 
    0x3, 0x2, 0x2, 0x2, 0x223, 0x224, 0x3, 0x2, 0x2, 0x2, 0x224, 0x227, 
    0x3, 0x2, 0x2, 0x2, 0x225, 0x223, 0x3, 0x2, 0x2, 0x2, 0x226, 0x21e, 
    0x3, 0x2, 0x2, 0x2, 0x226, 0x227, 0x3, 0x2, 0x2, 0x2, 0x227, 0x228, 
    0x3, 0x2, 0x2, 0x2, 0x228, 0x22a, 0x7, 0xa, 0x2, 0x2, 0x229, 0x1fa, 
    0x3, 0x2, 0x2, 0x2, 0x229, 0x1fb, 0x3, 0x2, 0x2, 0x2, 0x229, 0x1fc, 
    0x3, 0x2, 0x2, 0x2, 0x229, 0x1fd, 0x3, 0x2, 0x2, 0x2, 0x229, 0x1fe, 
    0x3, 0x2, 0x2, 0x2, 0x229, 0x202, 0x3, 0x2, 0x2, 0x2, 0x229, 0x210, 
    0x3, 0x2, 0x2, 0x2, 0x229, 0x211, 0x3, 0x2, 0x2, 0x2, 0x229, 0x21d, 
    0x3, 0x2, 0x2, 0x2, 0x22a, 0x39, 0x3, 0x2, 0x2, 0x2, 0x22b, 0x22d, 0x7, 
    0x38, 0x2, 0x2, 0x22c, 0x22b, 0x3, 0x2, 0x2, 0x2, 0x22c, 0x22d, 0x3, 
    0x2, 0x2, 0x2, 0x22d, 0x22e, 0x3, 0x2, 0x2, 0x2, 0x22e, 0x230, 0x7, 
    0x39, 0x2, 0x2, 0x22f, 0x231, 0x7, 0x3a, 0x2, 0x2, 0x230, 0x22f, 0x3, 
    0x2, 0x2, 0x2, 0x230, 0x231, 0x3, 0x2, 0x2, 0x2, 0x231, 0x3b, 0x3, 0x2, 
    0x2, 0x2, 0x45, 0x3f, 0x53, 0x57, 0x60, 0x6d, 0x72, 0x7b, 0x88, 0x8b, 
    0x8e, 0x92, 0xa0, 0xb8, 0xc0, 0xc3, 0xc9, 0xcd, 0xd5, 0xd8, 0xe0, 0xe8, 
    0xeb, 0xee, 0xf9, 0x100, 0x10b, 0x113, 0x11a, 0x121, 0x124, 0x12e, 0x138, 
    0x13b, 0x142, 0x14a, 0x152, 0x15a, 0x165, 0x16f, 0x178, 0x180, 0x18e, 
    0x196, 0x19f, 0x1a2, 0x1a7, 0x1b1, 0x1b4, 0x1bc, 0x1cc, 0x1d4, 0x1d7, 
    0x1db, 0x1df, 0x1ec, 0x1ef, 0x1f2, 0x1f6, 0x209, 0x20c, 0x217, 0x21a, 
    0x223, 0x226, 0x229, 0x22c, 0x230, 
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

#include "mimic_parser.hpp"

#include "fapc/codec/fap_table.hpp"
#include "fapc/codec/nesting_limit.hpp"
#include "fapc/transcoder/codes.hpp"
#include "mimic_lexer.hpp"

namespace fapc::mimic {
namespace {

// Mimic Table 1 (docs/mimic.md, "Grammar"): pname (no value), pname-arg (value), and
// left/right/connect which take either form (ParamName lists them in these three runs).
bool takes_no_value(ParamName n) { return n >= ParamName::linear; }
bool needs_value(ParamName n) { return n >= ParamName::in && n <= ParamName::max; }

bool is_keyword(std::string_view name) { return name == "main" || name == "def" || name == "defxpr"; }

class Parser {
 public:
  Parser(std::string_view source, const std::string& file, MainSink& sink)
      : lexer_(source, file), current_(lexer_.next()), source_(source), file_(file), sink_(sink) {}

  Status program(Program& program) {
    while (peek().kind == TokenKind::identifier && (peek().text == "def" || peek().text == "defxpr")) {
      Result<Definition> definition = define();
      if (!definition) return definition.error();
      program.definitions.push_back(std::move(*definition));
    }
    if (peek().kind != TokenKind::identifier || peek().text != "main") {
      return unexpected("'def', 'defxpr' or 'main'");
    }
    next();
    if (peek().kind == TokenKind::less) {
      Result<std::vector<Param>> params = parameters();
      if (!params) return params.error();
      program.main_params = std::move(*params);
    }
    sink_.begin_main(program.definitions, program.main_params);
    streaming_ = true;
    Result<Action> group = action_group({});
    if (!group) return group.error();
    if (peek().kind != TokenKind::end_of_input) return unexpected("the end of the program after main's group");
    return ok_status();
  }

 private:
  Lexer lexer_;
  Token current_;
  Token previous_;
  std::string_view source_;
  const std::string& file_;
  int depth_ = 0;  // groups open around the current token: the recursion is bounded by it
  MainSink& sink_;
  // parameters() and time_value_list() collect here, then copy out exactly what they read.
  std::vector<Param> params_read_;
  std::vector<Number> numbers_read_;
  bool streaming_ = false;  // inside main: groups and named actions go to sink_, not into a tree

  const Token& peek() const { return current_; }
  // Consumes the current token and returns it (valid until the next call).
  const Token& next() {
    previous_ = current_;
    if (current_.kind != TokenKind::end_of_input && current_.kind != TokenKind::error) {
      current_ = lexer_.next();
    }
    return previous_;
  }
  static Position position(const Token& t) { return Position{t.line, t.column}; }

  Diagnostic error_at(ErrorCode code, const Token& t, std::string message) const {
    return make_error(code, Location::text(file_, t.line, t.column), std::move(message), source_line(source_, t.line));
  }
  Diagnostic unexpected(const std::string& wanted) const {
    const Token& t = peek();
    if (t.kind == TokenKind::error) return lexer_.error();  // the lexer's message is the right one
    const std::string found = t.kind == TokenKind::end_of_input ? "the end of the program"
                              : t.kind == TokenKind::string     ? "\"" + t.str() + "\""
                                                                : "'" + t.str() + "'";
    return error_at(codes::mimic::syntax, t, "expected " + wanted + ", found " + found);
  }

  Result<Token> expect(TokenKind kind, const std::string& wanted) {
    if (peek().kind != kind) return unexpected(wanted);
    return next();
  }

  Result<Definition> define() {
    Definition definition;
    definition.expression = next().text == "defxpr";
    Result<Token> name = expect(TokenKind::identifier, "a name to define");
    if (!name) return name.error();
    if (is_keyword(name->text))
      return error_at(codes::mimic::keyword_as_name, *name, "'" + name->str() + "' is a keyword, not a name");
    definition.name = name->str();
    definition.at = position(*name);
    if (definition.expression) {
      Result<Token> file = expect(TokenKind::string, "a quoted expression file name (\"smile.xpr\")");
      if (!file) return file.error();
      definition.file = file->str();
      definition.file_at = position(*file);
      return definition;
    }
    Result<Action> group = action_group({});
    if (!group) return group.error();
    definition.group = std::move(*group);
    return definition;
  }

  // `params`: those written before the group (`< params > group`).
  Result<Action> action_group(std::vector<Param> params) {
    const Token open = peek();  // a copy: peek() moves on
    if (open.kind != TokenKind::left_brace && open.kind != TokenKind::left_bracket) {
      return unexpected("'{' (a sequence) or '[' (a parallel)");
    }
    if (depth_ >= kMaxNestingDepth) {
      return nesting_too_deep(Location::text(file_, open.line, open.column), "groups", source_line(source_, open.line));
    }
    ++depth_;
    Result<Action> group = group_body(open, std::move(params));
    --depth_;
    return group;
  }

  Result<Action> group_body(const Token& open, std::vector<Param> params) {
    Action group;
    group.params = std::move(params);
    group.kind = open.kind == TokenKind::left_brace ? Action::Kind::sequence : Action::Kind::parallel;
    group.at = position(open);
    const TokenKind close = group.kind == Action::Kind::sequence ? TokenKind::right_brace : TokenKind::right_bracket;
    next();
    if (peek().kind == close) {
      return error_at(codes::mimic::empty_group, peek(),
                      std::string("an empty ") + (group.kind == Action::Kind::sequence ? "sequence" : "parallel") +
                          ": a group needs at least one action");
    }
    if (streaming_) sink_.open_group(group);
    while (peek().kind != close) {
      if (peek().kind == TokenKind::end_of_input) {
        return error_at(codes::mimic::unclosed_group, open,
                        std::string("this '") + (close == TokenKind::right_brace ? "{" : "[") + "' is never closed");
      }
      Result<Action> child = action(close);
      if (!child) return child.error();
      if (!streaming_) {
        group.children.push_back(std::move(*child));
      } else if (child->kind == Action::Kind::named) {
        sink_.named_action(std::move(*child));
      }  // else a group, already given to the sink
    }
    next();
    if (streaming_) sink_.close_group();
    // The tree lives until the clips are made: no room kept for growth (a script holds millions).
    group.children.shrink_to_fit();
    return group;
  }

  Result<Action> action(TokenKind close) {
    if (peek().kind == TokenKind::less) {  // < params > group
      Result<std::vector<Param>> params = parameters();
      if (!params) return params.error();
      return action_group(std::move(*params));
    }
    if (peek().kind == TokenKind::left_brace || peek().kind == TokenKind::left_bracket) {
      return action_group({});
    }
    Result<Token> name = expect(TokenKind::identifier, "an action (a name, '{', '[' or '<')");
    if (!name) return name.error();
    if (is_keyword(name->text)) {
      return error_at(codes::mimic::definition_after_main, *name,
                      "'" + name->str() + "' must come before main, at the top of the program");
    }
    Action atomic;
    atomic.kind = Action::Kind::named;
    atomic.name = name->str();
    atomic.at = position(*name);
    if (peek().kind == TokenKind::less) {
      Result<std::vector<Param>> params = parameters();
      if (!params) return params.error();
      atomic.params = std::move(*params);
    }
    if (peek().kind == TokenKind::left_paren) {
      if (auto list = time_value_list(atomic); !list) return list.error();
      if (peek().kind == TokenKind::semicolon) next();
      return atomic;
    }
    // `;` ends an atomic action; it may be left out before the group's closing bracket.
    if (peek().kind == TokenKind::semicolon) {
      next();
    } else if (peek().kind != close) {
      return unexpected("';' after the action '" + atomic.name + "'");
    }
    return atomic;
  }

  Status time_value_list(Action& atomic) {
    atomic.has_list = true;
    atomic.list_at = position(next());
    for (std::vector<Number>* list : {&atomic.times, &atomic.values}) {
      numbers_read_.clear();
      while (peek().kind == TokenKind::number) {
        const Token& t = next();
        numbers_read_.push_back(Number{t.number, position(t)});
      }
      const char* wanted =
          list == &atomic.times ? "a time or ';' ending the times" : "a value or ';' ending the values";
      if (auto semicolon = expect(TokenKind::semicolon, wanted); !semicolon) return semicolon.error();
      list->assign(numbers_read_.begin(), numbers_read_.end());
    }
    if (auto close = expect(TokenKind::right_paren, "')' closing the time-value list"); !close) {
      return close.error();
    }
    return ok_status();
  }

  Result<std::vector<Param>> parameters() {
    next();  // <
    std::vector<Param>& params = params_read_;
    params.clear();
    for (;;) {
      Result<Token> name = expect(TokenKind::identifier, "a parameter name");
      if (!name) return name.error();
      const std::optional<ParamName> id = param_name(name->text);
      if (!id) {
        return error_at(codes::mimic::unknown_parameter, *name,
                        "unknown parameter " + quoted_name(name->text) +
                            " (expected left, right, in, hold, out, value, connect, "
                            "duration, freq, period, min, max, linear, sin, log, exp, "
                            "average, add or overwrite)");
      }
      Param param{*id, position(*name), std::nullopt};
      if (peek().kind == TokenKind::equals) {
        if (takes_no_value(param.id)) {
          return error_at(codes::mimic::parameter_value, peek(), "'" + param.name() + "' takes no value");
        }
        next();
        if (peek().kind == TokenKind::identifier) {
          return error_at(codes::mimic::parameter_value, peek(),
                          "'" + param.name() + "' takes a number, not the name '" + peek().str() + "'");
        }
        Result<Token> value = expect(TokenKind::number, "a number after '" + param.name() + "='");
        if (!value) return value.error();
        param.value = Number{value->number, position(*value)};
      } else if (needs_value(param.id)) {
        return error_at(codes::mimic::parameter_value, *name,
                        "'" + param.name() + "' needs a value ('" + param.name() + "=...')");
      }
      params.push_back(std::move(param));
      if (peek().kind == TokenKind::comma) {
        next();
        continue;
      }
      if (auto close = expect(TokenKind::greater, "',' or '>' in the parameter list"); !close) {
        return close.error();
      }
      // One allocation of the right size per list: a program has millions of them.
      return std::vector<Param>(params.begin(), params.end());
    }
  }
};

}  // namespace

Status parse_program(std::string_view source, const std::string& file_name, Program& program, MainSink& sink) {
  return Parser(source, file_name, sink).program(program);
}

}  // namespace fapc::mimic

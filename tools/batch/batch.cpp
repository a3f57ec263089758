#include "tools/batch/batch.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace ksmc::tools::batch {

namespace fs = std::filesystem;

std::vector<std::string> folder_names(const std::vector<fs::path>& inputs) {
  std::vector<std::string> out;
  std::set<std::string> used;
  for (const auto& in : inputs) {
    const std::string stem = in.stem().string().empty() ? "input" : in.stem().string();
    std::string name = stem;
    for (int k = 2; used.count(name); ++k) name = stem + "_" + std::to_string(k);
    used.insert(name);
    out.push_back(name);
  }
  return out;
}

namespace {

struct Running {
  std::size_t row = 0;
  std::chrono::steady_clock::time_point start;
};

pid_t spawn(const Request& r, const std::string& input, const fs::path& folder, const fs::path& log) {
  std::vector<std::string> args{r.binary.string(), input, "--out", folder.string(), "--quiet"};
  args.insert(args.end(), r.extra.begin(), r.extra.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

nlohmann::json read_summary(const fs::path& folder) {
  std::ifstream in(folder / "summary.json");
  if (!in) return nullptr;
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception&) {
    return nullptr;
  }
}

}  // namespace

std::vector<RunRow> run_all(const Request& r) {
  const auto names = folder_names(r.inputs);
  std::vector<RunRow> rows(r.inputs.size());
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  const unsigned jobs = r.jobs == 0 ? 1 : r.jobs;
  while (next < rows.size() || !running.empty()) {
    while (next < rows.size() && running.size() < jobs) {
      RunRow& row = rows[next];
      row.input = r.inputs[next].string();
      row.folder = names[next];
      const pid_t pid = spawn(r, row.input, r.out / row.folder, r.out / (row.folder + ".log"));
      if (pid < 0) {
        row.exit_code = -1;
      } else {
        running[pid] = {next, std::chrono::steady_clock::now()};
      }
      ++next;
    }
    if (running.empty()) continue;
    int status = 0;
    const pid_t done = waitpid(-1, &status, 0);
    if (done < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("ksmc-batch: waitpid failed");
    }
    const auto it = running.find(done);
    if (it == running.end()) continue;
    RunRow& row = rows[it->second.row];
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - it->second.start).count();
    row.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    row.summary = read_summary(r.out / row.folder);
    running.erase(it);
  }
  return rows;
}

namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string cell(const nlohmann::json& j, const char* key) {
  if (j.is_object() && j.contains(key) && j[key].is_number()) return number(j[key].get<double>());
  return "";
}

void flatten(const nlohmann::json& j, const std::string& prefix, std::vector<std::pair<std::string, double>>& out) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_number() && !it->is_boolean()) out.emplace_back(key, it->get<double>());
    if (it->is_object()) flatten(*it, key, out);
  }
}

std::string status_of(const RunRow& r) {
  if (r.exit_code == 0) return "ok";
  if (r.exit_code < 0) return "not started";
  return "exit " + std::to_string(r.exit_code);
}

}  // namespace

Table make_table(const std::vector<RunRow>& rows) {
  Table t;
  t.columns = {"input", "folder", "status", "seconds", "iterations", "iterations_per_second", "acceptance_rate",
               "best_log_posterior"};
  std::vector<std::vector<std::pair<std::string, double>>> extra(rows.size());
  std::map<std::string, std::size_t> column_of;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].summary.is_object() && rows[i].summary.contains("domain") && rows[i].summary["domain"].is_object())
      flatten(rows[i].summary["domain"], "", extra[i]);
    for (const auto& [k, v] : extra[i])
      if (!column_of.count(k)) {
        column_of[k] = t.columns.size();
        t.columns.push_back(k);
      }
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RunRow& r = rows[i];
    const nlohmann::json& s = r.summary;
    const nlohmann::json best = s.is_object() && s.contains("best") ? s["best"] : nlohmann::json();
    std::vector<std::string> row{r.input, r.folder, status_of(r), number(r.seconds), cell(s, "iterations"),
                                 cell(s, "iterations_per_second"), cell(s, "acceptance_rate"),
                                 cell(best, "log_posterior")};
    row.resize(t.columns.size());
    for (const auto& [k, v] : extra[i]) row[column_of[k]] = number(v);
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string to_csv(const Table& t) {
  auto quote = [](const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  std::string out;
  for (std::size_t c = 0; c < t.columns.size(); ++c) out += (c ? "," : "") + quote(t.columns[c]);
  out += "\n";
  for (const auto& row : t.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) out += (c ? "," : "") + quote(row[c]);
    out += "\n";
  }
  return out;
}

std::string to_markdown(const Table& t) {
  auto esc = [](const std::string& s) {
    std::string e;
    for (char c : s) e += c == '|' ? std::string("\\|") : std::string(1, c);
    return e;
  };
  std::string out = "|";
  for (const auto& c : t.columns) out += " " + esc(c) + " |";
  out += "\n|";
  for (std::size_t c = 0; c < t.columns.size(); ++c) out += "---|";
  out += "\n";
  for (const auto& row : t.rows) {
    out += "|";
    for (const auto& c : row) out += " " + esc(c) + " |";
    out += "\n";
  }
  return out;
}

}  // namespace ksmc::tools::batch

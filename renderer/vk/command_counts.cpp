#include "renderer/vk/command_counts.h"

#include <algorithm>

namespace raylab {

void CommandCounts::add(CommandKind kind) {
  switch (kind) {
    case CommandKind::Dispatch: ++directDispatches; break;
    case CommandKind::IndirectDispatch: ++indirectDispatches; break;
    case CommandKind::Barrier: ++barriers; break;
    case CommandKind::SizeWrite: ++sizeWrites; break;
  }
}

CommandCounts& CommandCounts::operator+=(const CommandCounts& o) {
  directDispatches += o.directDispatches;
  indirectDispatches += o.indirectDispatches;
  barriers += o.barriers;
  sizeWrites += o.sizeWrites;
  return *this;
}

void CommandTally::add(std::string_view stage, CommandKind kind) {
  auto it = std::find_if(stages_.begin(), stages_.end(), [&](const StageCommands& s) { return s.stage == stage; });
  if (it == stages_.end()) it = stages_.insert(stages_.end(), StageCommands{std::string(stage), {}});
  it->counts.add(kind);
}

CommandCounts CommandTally::total() const {
  CommandCounts sum;
  for (const StageCommands& s : stages_) sum += s.counts;
  return sum;
}

namespace {
// One open scope: the buffer, where its commands count, and the stack of stages entered in it.
struct OpenScope {
  VkCommandBuffer cmd;
  CommandTally* tally;
  std::vector<std::string> stages;
};
// A frame's recording opens one scope, so the list is short; the innermost scope of a buffer is its last.
thread_local std::vector<OpenScope> tScopes;

OpenScope* scopeOf(VkCommandBuffer cmd) {
  for (auto it = tScopes.rbegin(); it != tScopes.rend(); ++it)
    if (it->cmd == cmd) return &*it;
  return nullptr;
}
}  // namespace

CountCommands::CountCommands(VkCommandBuffer cmd, CommandTally& tally) { tScopes.push_back({cmd, &tally, {}}); }
CountCommands::~CountCommands() { tScopes.pop_back(); }

void countCommand(VkCommandBuffer cmd, CommandKind kind) {
  if (OpenScope* s = scopeOf(cmd)) s->tally->add(s->stages.empty() ? std::string_view() : s->stages.back(), kind);
}

void enterCommandStage(VkCommandBuffer cmd, std::string_view stage) {
  if (OpenScope* s = scopeOf(cmd)) s->stages.emplace_back(stage);
}

void leaveCommandStage(VkCommandBuffer cmd) {
  if (OpenScope* s = scopeOf(cmd); s && !s->stages.empty()) s->stages.pop_back();
}

}  // namespace raylab

#include "scene_overrides.h"

#include <GL/gl.h>
#include <glass/scene/frame_values.h>

#include <algorithm>
#include <set>

namespace glass::cli::view {

namespace {

// Calls function(list) on the program's statements, every definition's body, every begin/end
// body and every recursive IFS's base shape (for a const program or not).
template <typename List, typename Function> void visitLists(List &list, Function &function) {
  function(list);
  for (auto &statement : list) {
    if (auto *begin = std::get_if<scene::Begin>(&statement.body)) visitLists(begin->body, function);
    if (auto *ifs = std::get_if<scene::Ifs>(&statement.body)) visitLists(ifs->base, function);
  }
}

template <typename ProgramType, typename Function> void forEachStatementList(ProgramType &program, Function function) {
  visitLists(program.statements, function);
  for (auto &definition : program.definitions) visitLists(definition.body, function);
}

GLenum shadeModelOf(ShadeChoice choice) {
  switch (choice) {
    case ShadeChoice::Flat: return GL_FLAT;
    case ShadeChoice::Phong: return GL_PHONG_WIN;
    default: return GL_SMOOTH;
  }
}

} // namespace

std::vector<SceneLight> sceneLights(const scene::Program &program) {
  std::set<int> enabled;
  const scene::FrameValues values = scene::evaluateParameters(program, 0);
  // A light's default position (0, 0, 1, 0) is directional and its default cutoff 180 no spot
  // (OpenGL 1.4, table 2.10); each `light` statement changes what it sets, as its glLight
  // calls would.
  bool directional[8] = {true, true, true, true, true, true, true, true};
  bool spot[8] = {};
  forEachStatementList(program, [&](const scene::StatementList &list) {
    for (const scene::Statement &statement : list) {
      if (const auto *enable = std::get_if<scene::Enable>(&statement.body); enable && enable->enable) {
        for (scene::GLenumValue cap : enable->caps) {
          if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + 8) enabled.insert(static_cast<int>(cap - GL_LIGHT0));
        }
      }
      if (const auto *light = std::get_if<scene::Light>(&statement.body); light && light->index >= 0 && light->index < 8) {
        for (const scene::NamedValues &entry : light->values) {
          if (entry.pname == GL_POSITION && entry.values.size() == 4) {
            directional[light->index] = values(entry.values[3]) == 0.0;
          }
          if (entry.pname == GL_SPOT_CUTOFF && !entry.values.empty()) {
            spot[light->index] = values(entry.values[0]) != 180.0;
          }
        }
      }
    }
  });
  std::vector<SceneLight> lights;
  for (int number : enabled) {
    lights.push_back({number, spot[number] ? "spot" : directional[number] ? "directional" : "point"});
  }
  return lights;
}

bool hasRoundedModels(const scene::Program &program) {
  bool found = false;
  forEachStatementList(program, [&](const scene::StatementList &list) {
    for (const scene::Statement &statement : list) {
      if (const auto *model = std::get_if<scene::DrawModel>(&statement.body); model && model->round) found = true;
    }
  });
  return found;
}

scene::Program withOverrides(const scene::Program &program, const SceneOverrides &overrides, int frame) {
  scene::Program changed = program;
  const scene::FrameValues values = scene::evaluateParameters(program, frame);
  const GLenum shadeModel = shadeModelOf(overrides.shade);
  forEachStatementList(changed, [&](scene::StatementList &list) {
    for (scene::Statement &statement : list) {
      if (auto *shade = std::get_if<scene::ShadeModel>(&statement.body); shade && overrides.shade != ShadeChoice::Scene) {
        shade->mode = shadeModel;
      } else if (auto *mode = std::get_if<scene::PolygonMode>(&statement.body); mode && overrides.wireframe) {
        mode->face = GL_FRONT_AND_BACK;
        mode->mode = GL_LINE;
      } else if (auto *enable = std::get_if<scene::Enable>(&statement.body); enable && enable->enable) {
        std::erase_if(enable->caps, [&](scene::GLenumValue cap) {
          return cap >= GL_LIGHT0 && cap < GL_LIGHT0 + 8 &&
                 std::count(overrides.lightsOff.begin(), overrides.lightsOff.end(), static_cast<int>(cap - GL_LIGHT0)) > 0;
        });
      } else if (auto *model = std::get_if<scene::DrawModel>(&statement.body); model && model->round &&
                 overrides.roundingChange != 0.0) {
        model->round = scene::Number::of(std::max(0.0, values(*model->round) + overrides.roundingChange));
      }
    }
  });
  // Statements put before the scene's own (shade model first), at its first statement's place
  // for messages.
  const scene::SourceLocation where = program.statements.empty() ? scene::SourceLocation{} : program.statements.front().where;
  auto prepend = [&](auto body) {
    scene::Statement statement;
    statement.where = where;
    statement.body = body;
    changed.statements.insert(changed.statements.begin(), std::move(statement));
  };
  if (overrides.wireframe) prepend(scene::PolygonMode{GL_FRONT_AND_BACK, GL_LINE});
  if (overrides.shade != ShadeChoice::Scene) prepend(scene::ShadeModel{shadeModel});
  return changed;
}

} // namespace glass::cli::view

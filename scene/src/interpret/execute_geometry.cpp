// Geometry sent vertex by vertex: begin/end, rect, indexed meshes, OBJ and Wings3D models.
#include "interpret/executor.h"
#include "load/wings_model.h"


namespace glass::scene {

void Interpreter::Executor::run(const Begin &s) {
  if (options_.tracer != nullptr && options_.tracer->pending()) options_.tracer->capture();
  glBegin(s.mode);
  ++insideBegin_;
  execute(s.body);
  --insideBegin_;
  glEnd();
}

void Interpreter::Executor::run(const Rect &s) {
  std::vector<double> r = values(s.corners);
  VertexTracer *tracer = options_.tracer;
  if (tracer != nullptr && tracer->pending()) tracer->capture();
  glRectd(r[0], r[1], r[2], r[3]);
  if (tracer != nullptr) {
    // glRect is glBegin(GL_POLYGON) with these four vertices (OpenGL 1.1 section 2.9).
    const double corners[4][4] = {{r[0], r[1], 0, 1}, {r[2], r[1], 0, 1}, {r[2], r[3], 0, 1}, {r[0], r[3], 0, 1}};
    for (const auto &corner : corners) tracer->vertex(corner, current_->where, "'rect'");
  }
}

void Interpreter::Executor::run(const Mesh &s) {
  std::vector<float> positions = floats(s.positions);
  std::vector<float> normals = floats(s.normals);
  std::vector<float> colors = floats(s.colors);
  std::vector<float> texcoords = floats(s.texcoords);
  std::size_t count = positions.size() / static_cast<std::size_t>(s.positionSize);

  VertexTracer *tracer = options_.tracer;
  if (tracer != nullptr && tracer->pending()) {
    // What glDrawElements / glDrawArrays will send, vertex by vertex (glArrayElement order).
    tracer->capture();
    std::size_t sent = s.indexed ? s.indices.size() : count;
    for (std::size_t k = 0; k < sent; ++k) {
      std::size_t i = s.indexed ? s.indices[k] : k;
      if (!normals.empty()) {
        double n[3] = {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
        tracer->setNormal(n);
      }
      if (!colors.empty()) {
        std::size_t size = static_cast<std::size_t>(s.colorSize);
        double c[4] = {colors[size * i], colors[size * i + 1], colors[size * i + 2], size == 4 ? colors[size * i + 3] : 1.0};
        tracer->setColor(c);
      }
      std::size_t size = static_cast<std::size_t>(s.positionSize);
      double v[4] = {positions[size * i], positions[size * i + 1], size > 2 ? positions[size * i + 2] : 0.0,
                     size > 3 ? positions[size * i + 3] : 1.0};
      tracer->vertex(v, current_->where, "'mesh', element " + std::to_string(k) + " (vertex " + std::to_string(i) + ")");
    }
  }

  // The GL leaves the current values of the arrays drawn undefined after glDrawArrays and
  // glDrawElements (OpenGL 1.4, section 2.8); the mesh keeps the ones before it, so that a
  // colour or normal after it is the same on every GL.
  saveCurrentValues();
  glPushAttrib(GL_CURRENT_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(s.positionSize, GL_FLOAT, 0, positions.data());
  if (!normals.empty()) {
    glEnableClientState(GL_NORMAL_ARRAY);
    glNormalPointer(GL_FLOAT, 0, normals.data());
  }
  if (!colors.empty()) {
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(s.colorSize, GL_FLOAT, 0, colors.data());
  }
  if (!texcoords.empty()) {
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(s.texcoordSize, GL_FLOAT, 0, texcoords.data());
  }
  if (s.indexed) {
    glDrawElements(s.mode, static_cast<GLsizei>(s.indices.size()), GL_UNSIGNED_INT, s.indices.data());
  } else {
    glDrawArrays(s.mode, 0, static_cast<GLsizei>(count));
  }
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glPopAttrib();
  resendCurrentValues();
}

void Interpreter::Executor::run(const DrawModel &s) {
  const Model &model = program_.models[static_cast<std::size_t>(s.model)];
  if (s.round && model.roundable != nullptr) {
    const double radius = value(*s.round);
    std::shared_ptr<const std::vector<ModelPart>> rounded;
    try {
      if (!(radius >= 0.0)) throw geometry::RoundingError("the radius must be 0 or more");
      rounded = model.roundable->rounded.partsFor(*model.roundable, radius);
    } catch (const geometry::RoundingError &error) {
      fail("cannot round the model with radius " + formatModelNumber(radius) + ": " + error.what());
    }
    drawModelParts(model, *rounded, s);
    return;
  }
  drawModelParts(model, model.parts, s);
}

void Interpreter::Executor::drawModelParts(const Model &model, const std::vector<ModelPart> &parts, const DrawModel &s) {
  VertexTracer *tracer = options_.tracer;
  // The model's materials and textures are its own: the state before it comes back after it.
  if (tracer != nullptr && tracer->pending()) tracer->capture();
  saveCurrentValues();
  glPushAttrib(GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_ENABLE_BIT | GL_TEXTURE_BIT);
  for (const ModelPart &part : parts) {
    if (s.useMaterials && part.material >= 0) {
      const ModelMaterial &m = model.materials[static_cast<std::size_t>(part.material)];
      glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, m.ambient.data());
      glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, m.diffuse.data());
      glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, m.specular.data());
      glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, m.emission.data());
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, m.shininess);
      // Without lighting the GL uses the current colour: the diffuse colour stands in.
      glColor4fv(m.diffuse.data());
      if (tracer != nullptr && tracer->pending()) {
        tracer->setMaterial(GL_FRONT_AND_BACK, GL_AMBIENT, m.ambient.data(), 4);
        tracer->setMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE, m.diffuse.data(), 4);
        tracer->setMaterial(GL_FRONT_AND_BACK, GL_SPECULAR, m.specular.data(), 4);
        tracer->setMaterial(GL_FRONT_AND_BACK, GL_EMISSION, m.emission.data(), 4);
        tracer->setMaterial(GL_FRONT_AND_BACK, GL_SHININESS, &m.shininess, 1);
        const double color[4] = {m.diffuse[0], m.diffuse[1], m.diffuse[2], m.diffuse[3]};
        tracer->setColor(color);
      }
      if (m.texture >= 0) {
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, textures_[static_cast<std::size_t>(m.texture)]);
      } else if (model.roundable == nullptr) {
        glDisable(GL_TEXTURE_2D);
      }
      // A .wings model's materials carry no image (glass does not read Wings' embedded images):
      // the texture the scene has bound and enabled textures it, through the faces' charts.
    }
    std::size_t count = part.positions.size() / 3;
    if (tracer != nullptr && tracer->pending()) {
      for (std::size_t i = 0; i < count; ++i) {
        double n[3] = {part.normals[3 * i], part.normals[3 * i + 1], part.normals[3 * i + 2]};
        double v[4] = {part.positions[3 * i], part.positions[3 * i + 1], part.positions[3 * i + 2], 1.0};
        tracer->setNormal(n);
        tracer->vertex(v, current_->where, "'model' " + model.path);
      }
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, part.positions.data());
    glNormalPointer(GL_FLOAT, 0, part.normals.data());
    glTexCoordPointer(2, GL_FLOAT, 0, part.texcoords.data());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count));
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  }
  glPopAttrib();
  resendCurrentValues();
}

} // namespace glass::scene

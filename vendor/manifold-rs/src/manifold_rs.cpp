// Copyright © 2026 The µcad authors <info@microcad.xyz>
// SPDX-License-Identifier: Apache-2.0

#include "manifold_rs.h"

#include <manifold/manifold.h>
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring> // memcpy
#include <mutex>
#include <thread>

static_assert(static_cast<int>(::manifold::Manifold::Error::Cancelled) == 14,
              "src/lib.rs: Manifold::CANCELLED must match Manifold's Error::Cancelled");

namespace manifold_rs
{
    Polygons::Polygons() : polygons(std::make_unique<::manifold::Polygons>()) {}
    Polygons::Polygons(::manifold::Polygons &&polygons) : polygons(std::make_unique<::manifold::Polygons>(std::move(polygons))) {}
    Polygons::~Polygons() {}

    size_t Polygons::size() const
    {
        return polygons->size();
    }

    rust::Slice<const double> Polygons::get_as_slice(size_t index) const
    {
        auto &polygon = (*polygons)[index];
        return rust::Slice<const double>(static_cast<double *>((void *)polygon.data()), polygon.size() * 2);
    }

    Manifold::Manifold() : manifold(std::make_unique<::manifold::Manifold>()) {}
    Manifold::Manifold(::manifold::Manifold &&manifold) : manifold(std::make_unique<::manifold::Manifold>(std::move(manifold))) {}
    Manifold::~Manifold() {}

    bool Manifold::is_empty() const
    {
        return manifold->IsEmpty();
    }

    std::uint32_t Manifold::status() const
    {
        return static_cast<std::uint32_t>(manifold->Status());
    }

    std::unique_ptr<Polygons> Manifold::slice(double height) const
    {
        return std::make_unique<Polygons>(manifold->Slice(height));
    }

    std::unique_ptr<Polygons> Manifold::project() const
    {
        return std::make_unique<Polygons>(manifold->Project());
    }

    std::unique_ptr<Manifold> Manifold::trim_by_plane(double x, double y, double z, double offset) const
    {
        return std::make_unique<Manifold>(manifold->TrimByPlane({x, y, z}, offset));
    }

    std::unique_ptr<Manifold> Manifold::hull() const
    {
        return std::make_unique<Manifold>(manifold->Hull());
    }

    std::unique_ptr<Manifold> Manifold::translate(double x, double y, double z) const
    {
        return std::make_unique<Manifold>(manifold->Translate({x, y, z}));
    }

    std::unique_ptr<Manifold> Manifold::transformed(rust::Slice<const double> m) const
    {
        // rulemesh addition: a rigid or similarity placement, kept in double precision.
        assert(m.size() == 12);
        ::manifold::mat3x4 t;
        for (int c = 0; c < 4; ++c)
            t[c] = ::manifold::vec3(m[3 * c], m[3 * c + 1], m[3 * c + 2]);
        return std::make_unique<Manifold>(manifold->Transform(t));
    }

    std::unique_ptr<Manifold> Manifold::as_original() const
    {
        return std::make_unique<Manifold>(manifold->AsOriginal());
    }

    std::int32_t Manifold::original_id() const
    {
        return manifold->OriginalID();
    }

    std::size_t Manifold::num_tri() const
    {
        return manifold->NumTri();
    }

    std::unique_ptr<Manifold> Manifold::simplify(double tolerance) const
    {
        return std::make_unique<Manifold>(manifold->Simplify(tolerance));
    }

    std::unique_ptr<Manifold> Manifold::scale(double x, double y, double z) const
    {
        return std::make_unique<Manifold>(manifold->Scale({x, y, z}));
    }
    std::unique_ptr<Manifold> Manifold::rotate(double x_degrees, double y_degrees, double z_degrees) const
    {
        return std::make_unique<Manifold>(manifold->Rotate(x_degrees, y_degrees, z_degrees));
    }

    std::unique_ptr<Manifold> Manifold::refine(int32_t n) const
    {
        return std::make_unique<Manifold>(manifold->Refine(n));
    }

    std::unique_ptr<Manifold> Manifold::refine_to_length(double t) const
    {
        return std::make_unique<Manifold>(manifold->RefineToLength(t));
    }

    std::unique_ptr<Manifold> Manifold::refine_to_tolerance(double t) const
    {
        return std::make_unique<Manifold>(manifold->RefineToTolerance(t));
    }

    std::unique_ptr<Manifold> Manifold::smooth_by_normals(std::int32_t n) const
    {
        return std::make_unique<Manifold>(manifold->SmoothByNormals(n));
    }

    std::unique_ptr<Manifold> Manifold::smooth_out(double min_sharp_angle, double min_smoothness) const
    {
        return std::make_unique<Manifold>(manifold->SmoothOut(min_sharp_angle, min_smoothness));
    }

    /// Calculate normals for the manifold and return a new one.
    std::unique_ptr<Manifold> Manifold::calculate_normals(std::int32_t normal_idx, double min_sharp_angle) const
    {
        return std::make_unique<Manifold>(manifold->CalculateNormals(normal_idx, min_sharp_angle));
    }

    std::unique_ptr<Manifold> empty()
    {
        return std::make_unique<Manifold>();
    }

    std::unique_ptr<Manifold> tetrahedron()
    {
        return std::make_unique<Manifold>(::manifold::Manifold::Tetrahedron());
    }

    std::unique_ptr<Manifold> cube(double x_size, double y_size, double z_size)
    {
        return std::make_unique<Manifold>(::manifold::Manifold::Cube({x_size, y_size, z_size}));
    }

    std::unique_ptr<Manifold> sphere(double radius, uint32_t circular_segments)
    {
        return std::make_unique<Manifold>(::manifold::Manifold::Sphere(radius, circular_segments));
    }

    std::unique_ptr<Manifold> cylinder(double radius_low, double radius_height, double height, uint32_t circular_segments)
    {
        return std::make_unique<Manifold>(::manifold::Manifold::Cylinder(height, radius_low, radius_height, circular_segments));
    }

    std::unique_ptr<Manifold> union_(const Manifold &a, const Manifold &b)
    {
        return std::make_unique<Manifold>(a.manifold->Boolean(*b.manifold, ::manifold::OpType::Add));
    }

    std::unique_ptr<Manifold> intersection(const Manifold &a, const Manifold &b)
    {
        return std::make_unique<Manifold>(a.manifold->Boolean(*b.manifold, ::manifold::OpType::Intersect));
    }

    std::unique_ptr<Manifold> difference(const Manifold &a, const Manifold &b)
    {
        return std::make_unique<Manifold>(a.manifold->Boolean(*b.manifold, ::manifold::OpType::Subtract));
    }

    void ManifoldVec::push(const Manifold &m)
    {
        items.push_back(*m.manifold);
    }

    std::unique_ptr<ManifoldVec> manifold_vec()
    {
        return std::make_unique<ManifoldVec>();
    }

    // Runs `evaluate` (which evaluates a Manifold under `ctx`) with a
    // watchdog thread that cancels `ctx` after `timeout_ms` milliseconds;
    // Manifold checks the context between (and inside) its phases
    // (rulemesh addition).
    template <typename F>
    static ::manifold::Manifold watched(std::uint64_t timeout_ms, F evaluate)
    {
        ::manifold::ExecutionContext ctx;
        std::mutex mutex;
        std::condition_variable finished;
        bool done = false;
        std::thread watchdog([&]
                             {
            std::unique_lock<std::mutex> lock(mutex);
            if (!finished.wait_for(lock, std::chrono::milliseconds(timeout_ms), [&] { return done; }))
                ctx.Cancel(); });
        auto result = evaluate(ctx);
        {
            std::lock_guard<std::mutex> lock(mutex);
            done = true;
        }
        finished.notify_one();
        watchdog.join();
        return result;
    }

    std::unique_ptr<Manifold> batch_union(const ManifoldVec &parts, std::uint64_t timeout_ms)
    {
        auto united = ::manifold::Manifold::BatchBoolean(parts.items, ::manifold::OpType::Add);
        if (timeout_ms == 0)
        {
            united.Status(); // evaluates the deferred union
            return std::make_unique<Manifold>(std::move(united));
        }
        auto result = watched(timeout_ms, [&](::manifold::ExecutionContext &ctx)
                              {
            auto w = united.WithContext(ctx);
            w.Status(); // evaluates the deferred union under the context
            return w; });
        return std::make_unique<Manifold>(std::move(result));
    }

    std::unique_ptr<Manifold> simplify_mesh(const Mesh &mesh, double tolerance, std::uint64_t timeout_ms)
    {
        // Both the import (FromMeshGL under the context) and the
        // simplification check the context, so the watchdog bounds both.
        auto evaluate = [&](::manifold::ExecutionContext &ctx)
        {
            auto imported = ctx.FromMeshGL(*mesh.mesh);
            if (imported.Status() != ::manifold::Manifold::Error::NoError)
                return imported;
            auto simplified = imported.WithContext(ctx).Simplify(tolerance);
            simplified.Status(); // evaluates under the context
            return simplified;
        };
        if (timeout_ms == 0)
        {
            ::manifold::ExecutionContext ctx;
            return std::make_unique<Manifold>(evaluate(ctx));
        }
        return std::make_unique<Manifold>(watched(timeout_ms, evaluate));
    }

    Mesh::Mesh() : mesh(std::make_unique<::manifold::Mesh>()) {}

    Mesh::Mesh(::manifold::Mesh &&mesh) : mesh(std::make_unique<::manifold::Mesh>(std::move(mesh))) {}

    Mesh::~Mesh() {}

    std::uint32_t Mesh::num_props() const
    {
        return mesh->numProp;
    }

    std::unique_ptr<std::vector<float>> Mesh::vertices() const
    {
        return std::make_unique<std::vector<float>>(mesh->vertProperties);
    }

    std::unique_ptr<std::vector<uint32_t>> Mesh::indices() const
    {
        return std::make_unique<std::vector<uint32_t>>(mesh->triVerts);
    }

    std::unique_ptr<std::vector<uint32_t>> Mesh::run_original_ids() const
    {
        return std::make_unique<std::vector<uint32_t>>(mesh->runOriginalID);
    }

    std::unique_ptr<std::vector<uint32_t>> Mesh::run_indices() const
    {
        return std::make_unique<std::vector<uint32_t>>(mesh->runIndex);
    }

    std::unique_ptr<Mesh> mesh_from_manifold(const Manifold &manifold)
    {
        auto mesh = manifold.manifold->GetMeshGL(0);
        return std::make_unique<Mesh>(std::move(mesh));
    }

    std::unique_ptr<Manifold> manifold_from_mesh(const Mesh &mesh)
    {
        return std::make_unique<Manifold>(::manifold::Manifold(*mesh.mesh));
    }

    std::unique_ptr<Mesh> mesh_from_vertices(
        rust::Slice<const float> vertices,
        rust::Slice<const uint32_t> indices)
    {
        assert(vertices.size() % 3 == 0);
        assert(indices.size() % 3 == 0);
        ::manifold::Mesh mesh;
        mesh.numProp = 3;
        mesh.vertProperties = std::vector<float>(vertices.begin(), vertices.end());
        mesh.triVerts = std::vector<uint32_t>(indices.begin(), indices.end());

        return std::make_unique<Mesh>(std::move(mesh));
    }

    ::manifold::Polygons to_polygons(rust::Slice<const rust::Slice<const double>> multi_polygon_data)
    {
        ::manifold::Polygons polygons;
        for (auto &polygon_data : multi_polygon_data)
        {
            assert(polygon_data.size() % 2 == 0);

            // Create SimplePolygon from rust::Slice<const float> via memcpy
            // without using a loop
            ::manifold::SimplePolygon p(polygon_data.size() / 2);
            memcpy((void *)p.data(), polygon_data.data(), polygon_data.size() * sizeof(double));
            polygons.push_back(p);
        }
        return polygons;
    }

    std::unique_ptr<Manifold> extrude(
        rust::Slice<const rust::Slice<const double>> multi_polygon_data,
        double height, uint32_t divisions, double twist_degrees, double scale_top_x, double scale_top_y)
    {
        return std::make_unique<Manifold>(::manifold::Manifold::Extrude(to_polygons(multi_polygon_data), height, divisions, twist_degrees, {scale_top_x, scale_top_y}));
    }

    std::unique_ptr<Manifold> revolve(
        rust::Slice<const rust::Slice<const double>> multi_polygon_data,
        uint32_t circular_segments, double revolve_degrees)
    {
        return std::make_unique<Manifold>(::manifold::Manifold::Revolve(to_polygons(multi_polygon_data), circular_segments, revolve_degrees));
    }

} // namespace manifold_rs

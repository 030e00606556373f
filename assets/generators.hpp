#pragma once
/// @file The procedural asset generators, one per kind (one .cpp each). A generator draws every
/// choice from the stream it is given and returns the full-detail mesh (origin at the ground
/// contact point, Z up, metres), the class of the object node and the collision proxy.
#include "assets/library.hpp"
#include "assets/mesh_builder.hpp"
#include "core/rng.hpp"

namespace silva::assets {

/// A generated asset before LODs.
struct GeneratedAsset {
  Mesh mesh;              ///< Full-detail mesh with its parts.
  Role role;              ///< Class of the object node (the trunk for trees).
  CollisionProxy proxy;   ///< Solid proxy (shape None for ground vegetation).
};

/// Norway spruce grown by the branching generator (assets/species.hpp), sapling to mature (1-32 m).
GeneratedAsset generate_spruce(Rng& rng);
/// Scots pine, sapling to mature (1-28 m).
GeneratedAsset generate_pine(Rng& rng);
/// European larch, sapling to mature (1-30 m).
GeneratedAsset generate_larch(Rng& rng);
/// European beech, sapling to mature (1-32 m).
GeneratedAsset generate_beech(Rng& rng);
/// Silver birch, sapling to mature (1-24 m).
GeneratedAsset generate_birch(Rng& rng);
/// Pedunculate oak, sapling to mature (1-26 m).
GeneratedAsset generate_oak(Rng& rng);
/// Dead snag: 8-20 m grown trunk, branches mostly broken off short, most with a snapped top
/// (splinter and wood disc), 70 % with bare twig cards.
GeneratedAsset generate_dead_tree(Rng& rng);
/// Fallen dead tree lying along X (centred on the origin), 3.5-14 m, with its torn-up root plate
/// (soil disc and roots) at the -X end; obstacle role, capsule proxy along the trunk.
GeneratedAsset generate_fallen_tree(Rng& rng);
/// Stump: 0.3-0.9 m high, flared bark sides and a cut wood top.
GeneratedAsset generate_stump(Rng& rng);
/// Grass clump: 0.3-0.6 m, crossed grass-blade cards.
GeneratedAsset generate_grass(Rng& rng);
/// Fern: 0.5-1 m, tilted frond cards around the centre.
GeneratedAsset generate_fern(Rng& rng);
/// Shrub: 1-2 m, a few stems and blobs of leaf cards.
GeneratedAsset generate_shrub(Rng& rng);
/// Rock: 0.3-1.5 m, noise-displaced icosphere sunk a little into the ground.
GeneratedAsset generate_rock(Rng& rng);
/// Log: 3-6 m long, 0.3-0.6 m thick, lying along X with cut ends.
GeneratedAsset generate_log(Rng& rng);

/// Vertical-cylinder proxy from the ground up: radius r, height h.
CollisionProxy cylinder_proxy(float r, float h);

/// A random unit vector (uniform on the sphere).
Vec3f random_direction(Rng& rng);

/// Adds `count` leaf cards of half-size `half` scattered in an ellipsoid blob (radii `radii`)
/// around `center`, each with a random orientation; the caller has begun the part.
void add_card_blob(MeshBuilder& b, Rng& rng, const Vec3f& center, const Vec3f& radii, int count, float half);

}  // namespace silva::assets

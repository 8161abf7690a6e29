// Sylva import for Unity (2019.4 and later), an editor script: put this folder's files in
// an `Editor` folder of the project (SylvaWind.shader may go anywhere under Assets).
// What it does, for models exported with `sylva export --profile unity`:
// - FBX (`--format fbx`): Unity's FBX importer already builds a LODGroup from the file's
//   LOD group. This script turns every `<name>_collider_<i>` mesh into a convex
//   MeshCollider (its renderer removed) and gives every material a `<material>_wind.mat`
//   beside the model, on the Sylva/Wind shader with the material's colour.
// - glTF (.glb/.gltf through glTFast or UnityGLTF, which import no LODs): after the import
//   it writes `<file>_sylva.prefab` beside the file: the imported tree with a LODGroup made
//   from the children named `<name>_LOD0`, `<name>_LOD1`, ... (level i takes over below
//   50% / 2^i of the screen height, the last culled below 1%), the same convex
//   MeshColliders and wind materials. Re-importing the file rewrites the prefab.
// The unity profile writes the wind into TEXCOORD_1/2 with v flipped, because Unity's glTF
// importers flip v on every UV set; Unity's FBX importer flips nothing and the FBX carries
// the wind unflipped; either way the mesh's uv2 = (sway, flex), uv3 = (phase, flutter), as
// SylvaWind.shader reads them.
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using UnityEditor;
using UnityEngine;

public class SylvaTreePostprocessor : AssetPostprocessor
{
    static readonly Regex Collider = new Regex(@"_collider_\d+$");
    static readonly Regex Level = new Regex(@"_LOD(\d+)$");
    const string WindShader = "Sylva/Wind";

    // FBX and OBJ: colliders now; materials through OnAssignMaterialModel.
    void OnPostprocessModel(GameObject root)
    {
        AddColliders(root);
    }

    Material OnAssignMaterialModel(Material material, Renderer renderer)
    {
        Shader shader = Shader.Find(WindShader);
        if (shader == null || material == null) return null;
        string path = Folder(assetPath) + "/" + material.name + "_wind.mat";
        Material wind = AssetDatabase.LoadAssetAtPath<Material>(path);
        if (wind == null)
        {
            wind = new Material(shader) { name = material.name + "_wind" };
            wind.SetColor("_Color", material.color);
            AssetDatabase.CreateAsset(wind, path);
        }
        return wind;
    }

    static void OnPostprocessAllAssets(string[] imported, string[] deleted, string[] moved,
                                       string[] movedFrom)
    {
        foreach (string path in imported)
        {
            string ext = Path.GetExtension(path).ToLowerInvariant();
            if (ext != ".glb" && ext != ".gltf") continue;
            string asset = path;
            EditorApplication.delayCall += () => MakePrefab(asset);
        }
    }

    static void MakePrefab(string path)
    {
        GameObject model = AssetDatabase.LoadAssetAtPath<GameObject>(path);
        if (model == null) return;
        GameObject tree = Object.Instantiate(model);
        tree.name = model.name;
        AddLodGroups(tree.transform);
        AddColliders(tree);
        string folder = Folder(path);
        foreach (Renderer r in tree.GetComponentsInChildren<Renderer>(true))
        {
            Material[] materials = r.sharedMaterials;
            for (int i = 0; i < materials.Length; ++i)
                materials[i] = WindMaterial(folder, materials[i]);
            r.sharedMaterials = materials;
        }
        string prefab = folder + "/" + Path.GetFileNameWithoutExtension(path) + "_sylva.prefab";
        PrefabUtility.SaveAsPrefabAsset(tree, prefab);
        Object.DestroyImmediate(tree);
    }

    // The asset's folder with forward slashes, as the AssetDatabase wants paths.
    static string Folder(string assetPath)
    {
        return Path.GetDirectoryName(assetPath).Replace('\\', '/');
    }

    static Material WindMaterial(string folder, Material material)
    {
        Shader shader = Shader.Find(WindShader);
        if (shader == null || material == null) return material;
        string path = folder + "/" + material.name + "_wind.mat";
        Material wind = AssetDatabase.LoadAssetAtPath<Material>(path);
        if (wind == null)
        {
            wind = new Material(shader) { name = material.name + "_wind" };
            Color color = material.HasProperty("baseColorFactor") ? material.GetColor("baseColorFactor")
                        : material.HasProperty("_BaseColor") ? material.GetColor("_BaseColor")
                        : material.color;
            wind.SetColor("_Color", color);
            AssetDatabase.CreateAsset(wind, path);
        }
        return wind;
    }

    // A LODGroup on every node whose children are `<name>_LOD<i>` for two or more i.
    static void AddLodGroups(Transform node)
    {
        var levels = new SortedDictionary<int, Transform>();
        foreach (Transform child in node)
        {
            Match m = Level.Match(child.name);
            if (m.Success) levels[int.Parse(m.Groups[1].Value)] = child;
        }
        if (levels.Count >= 2 && node.GetComponent<LODGroup>() == null)
        {
            var lods = new List<LOD>();
            int i = 0;
            foreach (Transform level in levels.Values)
            {
                float height = i == levels.Count - 1 ? 0.01f : 0.5f / (1 << i);
                lods.Add(new LOD(height, level.GetComponentsInChildren<Renderer>(true)));
                ++i;
            }
            LODGroup group = node.gameObject.AddComponent<LODGroup>();
            group.SetLODs(lods.ToArray());
            group.RecalculateBounds();
            return;
        }
        foreach (Transform child in node) AddLodGroups(child);
    }

    // `<name>_collider_<i>` meshes become convex MeshColliders without a renderer.
    static void AddColliders(GameObject root)
    {
        foreach (MeshFilter filter in root.GetComponentsInChildren<MeshFilter>(true))
        {
            if (!Collider.IsMatch(filter.gameObject.name)) continue;
            MeshCollider collider = filter.gameObject.AddComponent<MeshCollider>();
            collider.sharedMesh = filter.sharedMesh;
            collider.convex = true;
            Renderer renderer = filter.GetComponent<Renderer>();
            if (renderer != null) Object.DestroyImmediate(renderer, true);
        }
    }
}

using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Viewer.Tests;

/// <summary>Reads the viewer page's state and canvas pixels, and computes where bodies are from a trace line.</summary>
internal static class PageProbe
{
    /// <summary>Team colours and the ball colour of the page (docs/viewer.md).</summary>
    public static readonly (int R, int G, int B)[] Team = [(0xd9, 0x48, 0x3b), (0x2f, 0x6f, 0xd6), (0x2e, 0x9e, 0x5b), (0x9b, 0x51, 0xc9)];

    public static readonly (int R, int G, int B) Ball = (0xf2, 0x9b, 0x30);

    /// <summary>Opens a replay page file (with <paramref name="fragment"/>, e.g. <c>#cycle=40</c>) with every request but the page itself aborted and recorded, once its first frame is drawn.</summary>
    public static async Task<(IPage Page, List<string> Errors, List<string> Requests)> OpenFile(Browser browser, string path, string fragment = "")
    {
        var (page, errors) = await browser.NewPageAsync();
        string url = new Uri(path).AbsoluteUri;
        var requests = new List<string>();
        page.Request += (_, r) =>
        {
            lock (requests)
            {
                requests.Add(r.Url);
            }
        };
        await page.Context.RouteAsync("**/*", route => route.Request.Url == url ? route.ContinueAsync() : route.AbortAsync());
        await page.GotoAsync(url + fragment);
        await page.WaitForFunctionAsync("() => window.urwpg && urwpg.firstFrameAt !== null", null, new() { Timeout = Browser.HangMs });
        return (page, errors, requests);
    }

    /// <summary>Waits until the page has drawn the frame of its current state (two animation frames).</summary>
    public static Task Settle(IPage page) => page.EvaluateAsync("() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))");

    /// <summary>Moves the scrub bar to a cycle index as a user does (value + input event) and waits for the frame.</summary>
    public static async Task Scrub(IPage page, int index)
    {
        await page.EvaluateAsync("k => { const s = document.getElementById('scrub'); s.value = String(k); s.dispatchEvent(new Event('input', { bubbles: true })); }", index);
        await Settle(page);
    }

    /// <summary>The page's current cycle index.</summary>
    public static Task<int> Cycle(IPage page) => page.EvaluateAsync<int>("() => urwpg.cycle");

    /// <summary>The RGB of the canvas at the canvas pixels of the given world points (the page's own world-to-canvas map).</summary>
    public static async Task<(int R, int G, int B)[]> Pixels(IPage page, IReadOnlyList<Vector2> points)
    {
        var flat = new List<double>();
        foreach (var p in points)
        {
            flat.Add(p.X);
            flat.Add(p.Y);
        }

        var rgb = await page.EvaluateAsync<int[]>(
            "pts => { const c = document.getElementById('pool').getContext('2d'); const out = []; " +
            "for (let i = 0; i < pts.length; i += 2) { const q = urwpg.worldToCanvas(pts[i], pts[i + 1]); " +
            "const d = c.getImageData(Math.floor(q[0]), Math.floor(q[1]), 1, 1).data; out.push(d[0], d[1], d[2]); } return out; }",
            flat.ToArray());
        var result = new (int, int, int)[points.Count];
        for (int i = 0; i < result.Length; i++)
        {
            result[i] = (rgb[3 * i], rgb[(3 * i) + 1], rgb[(3 * i) + 2]);
        }

        return result;
    }

    /// <summary>Whether two colours agree to within 3 per channel.</summary>
    public static bool Near((int R, int G, int B) a, (int R, int G, int B) b) =>
        Math.Abs(a.R - b.R) <= 3 && Math.Abs(a.G - b.G) <= 3 && Math.Abs(a.B - b.B) <= 3;

    /// <summary>The fish models (library truth) of a trace line, in fish order.</summary>
    public static FishModel[] Fish(JsonElement line, JsonElement layout)
    {
        var fish = line.GetProperty("fish");
        var models = new FishModel[fish.GetArrayLength()];
        for (int i = 0; i < models.Length; i++)
        {
            var f = fish[i];
            var s = layout.GetProperty("fish")[i].GetProperty("size");
            var j = s.GetProperty("joints");
            var size = new FishSize(s.GetProperty("length").GetSingle(), s.GetProperty("width").GetSingle(), s.GetProperty("head").GetSingle(), j[0].GetSingle(), j[1].GetSingle(), j[2].GetSingle());
            var joints = f.GetProperty("joints");
            models[i] = new FishModel(size, new FishPose(Point(f.GetProperty("position")), f.GetProperty("heading").GetSingle(), joints[0].GetSingle(), joints[1].GetSingle(), joints[2].GetSingle()));
        }

        return models;
    }

    /// <summary>A trace point.</summary>
    public static Vector2 Point(JsonElement p) => new(p[0].GetSingle(), p[1].GetSingle());

    /// <summary>Signed distance from a point to a convex polygon's boundary: positive inside.</summary>
    public static float Inside(ReadOnlySpan<Vector2> polygon, Vector2 p)
    {
        float area = 0;
        for (int i = 0; i < polygon.Length; i++)
        {
            var a = polygon[i];
            var b = polygon[(i + 1) % polygon.Length];
            area += (a.X * b.Y) - (b.X * a.Y);
        }

        float sign = MathF.Sign(area), best = float.MaxValue;
        for (int i = 0; i < polygon.Length; i++)
        {
            var a = polygon[i];
            var e = polygon[(i + 1) % polygon.Length] - a;
            float d = sign * ((e.X * (p.Y - a.Y)) - (e.Y * (p.X - a.X))) / e.Length();
            best = MathF.Min(best, d);
        }

        return best;
    }

    /// <summary>The centroid of a polygon's vertices.</summary>
    public static Vector2 Centroid(ReadOnlySpan<Vector2> polygon)
    {
        Vector2 sum = Vector2.Zero;
        foreach (var v in polygon)
        {
            sum += v;
        }

        return sum / polygon.Length;
    }

    /// <summary>Fails with the collected errors of a page.</summary>
    public static void NoErrors(List<string> errors)
    {
        lock (errors)
        {
            Assert.True(errors.Count == 0, "the page reported errors:\n" + string.Join("\n", errors));
        }
    }
}

import numpy as np, sys
def auc(score, pos):
    # AUC of score for positives (higher score = more likely positive), ties averaged
    from scipy.stats import rankdata
    r = rankdata(score); n1 = pos.sum(); n0 = len(pos) - n1
    return (r[pos].sum() - n1 * (n1 + 1) / 2) / (n1 * n0)
names = "support err_jet share lead cluster_share agree10 inl_frac err err_refit err_own ratio own_gain".split()
for d in sys.argv[1:]:
    a = np.loadtxt(d + ".txt"); c = dict(zip(names, a.T))
    pos = c["err"] > 10
    print(f"{d}: >10 {pos.mean()*100:.2f}%  refit>10 {(c['err_refit']>10).mean()*100:.2f}%  own>10 {(c['err_own']>10).mean()*100:.2f}%  rms {np.sqrt((c['err']**2).mean()):.2f} refit rms {np.sqrt((c['err_refit']**2).mean()):.2f} quad>10 {(c['err_jet']>10).mean()*100:.2f}% quad rms {np.sqrt((c['err_jet']**2).mean()):.2f}")
    for f in ["support", "share", "lead", "cluster_share", "agree10", "inl_frac"]:
        print(f"   AUC 1-{f}: {auc(-c[f], pos):.3f}", end="")
    print()
    for combo, v in [("share*inl", c["share"]*c["inl_frac"]), ("lead*inl", c["lead"]*c["inl_frac"]), ("lead*inl*clus", c["lead"]*c["inl_frac"]*c["cluster_share"]), ("share*inl*clus", c["share"]*c["inl_frac"]*c["cluster_share"])]:
        print(f"   AUC {combo}: {auc(-v, pos):.3f}", end="")
    print()

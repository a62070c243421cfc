// Scratch comparison (stop 32, not kept): the Morton order's LSD radix sort with two 16-bit digits (DiscTable today) against digits of at most 11 bits, on 1e6 keys of the thesis layout; same order asserted. Run: java -Xmx4g MortonSortDigits.java
import java.util.*;
public class MortonSortDigits {
  static int spread(int v){v&=0xFFFF;v=(v|(v<<8))&0x00FF00FF;v=(v|(v<<4))&0x0F0F0F0F;v=(v|(v<<2))&0x33333333;return (v|(v<<1))&0x55555555;}
  static int[] old(int[] key0){int n=key0.length;int[] key=key0.clone();int[] ids=new int[n];for(int i=0;i<n;i++)ids[i]=i;int[] ids2=new int[n],key2=new int[n];int[] counts=new int[1<<16];
    for(int pass=0;pass<2;pass++){int shift=16*pass;Arrays.fill(counts,0);for(int i=0;i<n;i++)counts[(key[i]>>>shift)&0xFFFF]++;int sum=0;for(int b=0;b<counts.length;b++){int c=counts[b];counts[b]=sum;sum+=c;}
      for(int i=0;i<n;i++){int at=counts[(key[i]>>>shift)&0xFFFF]++;ids2[at]=ids[i];key2[at]=key[i];}int[] t=ids;ids=ids2;ids2=t;t=key;key=key2;key2=t;}return ids;}
  static int[] neu(int[] key0, int bits){int n=key0.length;int[] key=key0.clone();int[] ids=new int[n];for(int i=0;i<n;i++)ids[i]=i;int[] ids2=new int[n],key2=new int[n];
    int passes=Math.max(1,(bits+10)/11);int digit=(bits+passes-1)/passes;int mask=(1<<digit)-1;int[] counts=new int[1<<digit];
    for(int pass=0;pass<passes;pass++){int shift=digit*pass;Arrays.fill(counts,0);for(int i=0;i<n;i++)counts[(key[i]>>>shift)&mask]++;int sum=0;for(int b=0;b<counts.length;b++){int c=counts[b];counts[b]=sum;sum+=c;}
      for(int i=0;i<n;i++){int at=counts[(key[i]>>>shift)&mask]++;ids2[at]=ids[i];key2[at]=key[i];}int[] t=ids;ids=ids2;ids2=t;t=key;key=key2;key2=t;}return ids;}
  public static void main(String[] a){int side=1000;int cells=1250;Random r=new Random(1);int n=side*side;int[] key=new int[n];int max=0;
    for(int row=0;row<side;row++)for(int c=0;c<side;c++){double x=c+0.5+0.2*(r.nextDouble()-0.5),y=row+0.5+0.2*(r.nextDouble()-0.5);int cc=(int)(x*cells/side),rr=(int)(y*cells/side);int k=spread(cc)|(spread(rr)<<1);key[row*side+c]=k;max=Math.max(max,k);}
    int bits=32-Integer.numberOfLeadingZeros(max);System.out.println("bits "+bits);
    if(!Arrays.equals(old(key),neu(key,bits)))throw new AssertionError("differ");
    for(int rep=0;rep<12;rep++){long t0=System.nanoTime();int[] o=old(key);long t1=System.nanoTime();int[] q=neu(key,bits);long t2=System.nanoTime();System.out.printf("old %.1f ms new %.1f ms%n",(t1-t0)/1e6,(t2-t1)/1e6);}
  }
}
